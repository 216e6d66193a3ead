// SPDX-License-Identifier: Apache-2.0
// Synthetic rectify maps (shift, rotation, barrel) quantised as the host does: shared by the
// rectify tests (tests/rectify/random_maps.hpp) and `scw vectors rectify`.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "hls/rectify/rectify_params.hpp"

namespace scw::rectify {

/// Clamps a position to the host's range [-S, W*S] x [-S, H*S] (every position outside it
/// samples only zeros, as the clamped one does).
inline hls::rectify::MapPoint clamp_point(hls::rectify::MapPoint p, int width, int height,
                                          int frac_bits) {
  const std::int32_t s = std::int32_t{1} << frac_bits;
  p.x = std::clamp(p.x, -s, width * s);
  p.y = std::clamp(p.y, -s, height * s);
  return p;
}

/// Quantises a position in pixels as the host does (cvRound(x * 2^F): round half to even in the
/// default rounding mode), then clamps it.
inline hls::rectify::MapPoint quantise_point(double x, double y, int width, int height,
                                             int frac_bits) {
  const double s = static_cast<double>(1 << frac_bits);
  // Clamp in double first so far-away positions cannot overflow the integer conversion.
  const double lim = 4.0 * (std::max(width, height) + 1) * s;
  hls::rectify::MapPoint p;
  p.x = static_cast<std::int32_t>(std::lrint(std::clamp(x * s, -lim, lim)));
  p.y = static_cast<std::int32_t>(std::lrint(std::clamp(y * s, -lim, lim)));
  return clamp_point(p, width, height, frac_bits);
}

namespace detail {

template <typename Fn>
std::vector<hls::rectify::MapPoint> warp_map(int width, int height, int frac_bits, Fn&& source) {
  std::vector<hls::rectify::MapPoint> m(static_cast<std::size_t>(width) *
                                        static_cast<std::size_t>(height));
  for (int v = 0; v < height; ++v)
    for (int u = 0; u < width; ++u) {
      double x = 0, y = 0;
      source(u, v, x, y);
      m[static_cast<std::size_t>(v) * width + u] = quantise_point(x, y, width, height, frac_bits);
    }
  return m;
}

}  // namespace detail

/// Output (u, v) samples raw (u + dx, v + dy), in pixels.
inline std::vector<hls::rectify::MapPoint> shift_map(int width, int height, int frac_bits,
                                                     double dx, double dy) {
  return detail::warp_map(width, height, frac_bits, [&](int u, int v, double& x, double& y) {
    x = u + dx;
    y = v + dy;
  });
}

/// Output (u, v) samples raw c + R(angle) ((u, v) - c): the image turned by `angle_deg` degrees
/// about the centre (cx, cy), in pixels.
inline std::vector<hls::rectify::MapPoint> rotation_map(int width, int height, int frac_bits,
                                                        double angle_deg, double cx, double cy) {
  const double a = angle_deg * 3.14159265358979323846 / 180.0;
  const double c = std::cos(a), s = std::sin(a);
  return detail::warp_map(width, height, frac_bits, [&](int u, int v, double& x, double& y) {
    x = cx + c * (u - cx) - s * (v - cy);
    y = cy + s * (u - cx) + c * (v - cy);
  });
}

/// Radial distortion about the image centre c: output (u, v) samples raw c + (p - c)(1 + k1 r^2),
/// r = |p - c| / half the image diagonal (r = 1 at the corners). k1 < 0 undoes barrel distortion
/// (the raw image's edges are squeezed, so samples are pulled towards the centre: -0.3 is
/// strong), k1 > 0 undoes pincushion distortion (corners sample outside the image).
inline std::vector<hls::rectify::MapPoint> barrel_map(int width, int height, int frac_bits,
                                                      double k1) {
  const double cx = (width - 1) / 2.0, cy = (height - 1) / 2.0;
  const double r2n = cx * cx + cy * cy;
  return detail::warp_map(width, height, frac_bits, [&](int u, int v, double& x, double& y) {
    const double du = u - cx, dv = v - cy;
    const double f = 1.0 + k1 * (r2n > 0 ? (du * du + dv * dv) / r2n : 0.0);
    x = cx + du * f;
    y = cy + dv * f;
  });
}

}  // namespace scw::rectify
