// SPDX-License-Identifier: Apache-2.0
// Central moments and Hu invariants: exact integer numerators, one rounding where possible.
#include "host/labelling/hu_moments.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>

namespace scw::labelling {
namespace {

using hls::labelling::Object;

// GCC's 128-bit integer; __extension__ keeps -Wpedantic quiet about a non-ISO type.
__extension__ typedef __int128 i128;

// m00 mu_pq for order 2 and m00^2 mu_pq for order 3: integers, because the centroid's
// denominators clear. A double evaluation (m30 - cx (3 mu20 + cx m10), as cv::moments does)
// subtracts numbers of size m00 x^3 to get one that may be many digits smaller; here the
// subtraction is exact.
struct Numerators {
  i128 c20, c11, c02, c30, c21, c12, c03;
};

Numerators numerators(const Object& o) {
  // Every term below is at most 2 (m00 X)^3, X = largest coordinate + 1, and there are at most
  // three such terms of each sign: m00 X < 2^40 keeps every partial sum below 2^123.
  const std::uint64_t extent = std::max(o.x_max, o.y_max) + std::uint64_t{1};
  if (o.area != 0 && o.area * extent >= (std::uint64_t{1} << 40))
    throw std::overflow_error(
        "hu_moments: the object is too large for exact 128-bit central moments "
        "(area x (largest coordinate + 1) must be below 2^40)");
  const i128 n = o.area, m10 = o.m10, m01 = o.m01, m20 = o.m20, m11 = o.m11, m02 = o.m02;
  const i128 m30 = o.m30, m21 = o.m21, m12 = o.m12, m03 = o.m03;
  Numerators c;
  c.c20 = n * m20 - m10 * m10;
  c.c11 = n * m11 - m10 * m01;
  c.c02 = n * m02 - m01 * m01;
  c.c30 = n * n * m30 - 3 * n * m20 * m10 + 2 * m10 * m10 * m10;
  c.c21 = n * n * m21 - 2 * n * m11 * m10 - n * m20 * m01 + 2 * m10 * m10 * m01;
  c.c12 = n * n * m12 - 2 * n * m11 * m01 - n * m02 * m10 + 2 * m01 * m01 * m10;
  c.c03 = n * n * m03 - 3 * n * m02 * m01 + 2 * m01 * m01 * m01;
  return c;
}

long double ld(i128 v) { return static_cast<long double>(v); }

}  // namespace

std::array<double, 7> central_moments(const Object& o) {
  if (o.area == 0) return {};
  const Numerators c = numerators(o);
  const long double n = o.area;
  const long double n2 = n * n;  // exact: area < 2^32
  return {static_cast<double>(ld(c.c20) / n),  static_cast<double>(ld(c.c11) / n),
          static_cast<double>(ld(c.c02) / n),  static_cast<double>(ld(c.c30) / n2),
          static_cast<double>(ld(c.c21) / n2), static_cast<double>(ld(c.c12) / n2),
          static_cast<double>(ld(c.c03) / n2)};
}

std::array<double, 7> hu_moments(const Object& o) {
  if (o.area == 0) return {};
  const Numerators c = numerators(o);
  const long double n = o.area;
  // eta_pq = mu_pq / n^(1 + (p + q) / 2): order 2 is c / n^3, order 3 is c / n^4.5.
  const long double inv2 = 1.0L / (n * n * n);
  const long double inv3 = 1.0L / (n * n * n * n * std::sqrt(n));
  // The sums and differences Hu's formulas are built from, formed exactly before scaling.
  const long double s = ld(c.c20 + c.c02) * inv2;       // eta20 + eta02
  const long double d = ld(c.c20 - c.c02) * inv2;       // eta20 - eta02
  const long double e = ld(c.c11) * inv2;               // eta11
  const long double t0 = ld(c.c30 + c.c12) * inv3;      // eta30 + eta12
  const long double t1 = ld(c.c21 + c.c03) * inv3;      // eta21 + eta03
  const long double q0 = ld(c.c30 - 3 * c.c12) * inv3;  // eta30 - 3 eta12
  const long double q1 = ld(3 * c.c21 - c.c03) * inv3;  // 3 eta21 - eta03
  const long double a = t0 * (t0 * t0 - 3 * t1 * t1);
  const long double b = t1 * (3 * t0 * t0 - t1 * t1);
  return {static_cast<double>(s),
          static_cast<double>(d * d + 4 * e * e),
          static_cast<double>(q0 * q0 + q1 * q1),
          static_cast<double>(t0 * t0 + t1 * t1),
          static_cast<double>(q0 * a + q1 * b),
          static_cast<double>(d * (t0 * t0 - t1 * t1) + 4 * e * t0 * t1),
          static_cast<double>(q1 * a - q0 * b)};
}

}  // namespace scw::labelling
