// SPDX-License-Identifier: Apache-2.0
// The labelling reference: partitions against cv::connectedComponentsWithStats, the join rule,
// validity and descriptors by hand, Hu moments against cv::HuMoments, Tsukuba's ground truth.
#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "hls/labelling/labelling_params.hpp"
#include "host/io/tsukuba.hpp"
#include "host/labelling/hu_moments.hpp"
#include "host/reference/labelling_ref.hpp"

namespace {

using scw::hls::labelling::joins;
using scw::hls::labelling::LabellingConfig;
using scw::hls::labelling::Object;
using scw::labelling::central_moments;
using scw::labelling::hu_moments;
using scw::reference::labelling_reference;
using scw::reference::LabellingReference;

// GCC's 128-bit integer, for exact central moments summed pixel by pixel.
__extension__ typedef __int128 i128;

/// A row-major map of Q11.4 disparities.
struct Map {
  int width = 0, height = 0;
  std::vector<std::uint16_t> d;
  Map(int w, int h) : width(w), height(h), d(static_cast<std::size_t>(w) * h, 0) {}
  std::uint16_t& at(int x, int y) { return d[static_cast<std::size_t>(y) * width + x]; }
};

Map from_rows(const std::vector<std::vector<std::uint16_t>>& rows) {
  Map m(static_cast<int>(rows.front().size()), static_cast<int>(rows.size()));
  for (int y = 0; y < m.height; ++y)
    for (int x = 0; x < m.width; ++x) m.at(x, y) = rows[y][x];
  return m;
}

Map from_mat(const cv::Mat& img) {  // CV_8U or CV_16U, one channel
  cv::Mat d16;
  img.convertTo(d16, CV_16U);
  Map m(d16.cols, d16.rows);
  for (int y = 0; y < m.height; ++y)
    for (int x = 0; x < m.width; ++x) m.at(x, y) = d16.at<std::uint16_t>(y, x);
  return m;
}

LabellingReference run(const Map& m, int floor = 0, int min_area = 1) {
  LabellingConfig cfg;  // size and tiles are not read by the reference
  cfg.floor = floor;
  cfg.min_area = min_area;
  return labelling_reference(m.d.data(), m.width, m.height, cfg);
}

/// Every valid pixel holds `value` with probability permille / 1000: all valid 4-neighbours join.
Map random_binary_map(int w, int h, int permille, std::uint32_t seed, std::uint16_t value = 160) {
  std::mt19937 rng(seed);
  Map m(w, h);
  for (auto& d : m.d) d = static_cast<int>(rng() % 1000) < permille ? value : 0;
  return m;
}

/// Overlapping rectangles of random disparity, +-4 of noise and some holes: objects that the
/// join rule (not just validity) cuts apart.
Map random_disparity_map(int w, int h, std::uint32_t seed) {
  std::mt19937 rng(seed);
  cv::Mat img(h, w, CV_16U, cv::Scalar(0));
  for (int i = 0; i < 12; ++i) {
    const int x = static_cast<int>(rng() % w), y = static_cast<int>(rng() % h);
    const int rw = 4 + static_cast<int>(rng() % (w / 2)),
              rh = 4 + static_cast<int>(rng() % (h / 2));
    cv::rectangle(img, cv::Rect(x, y, rw, rh), cv::Scalar(16 * (5 + rng() % 40)), cv::FILLED);
  }
  Map m = from_mat(img);
  for (auto& d : m.d) {
    if (d == 0) continue;
    if (rng() % 100 < 8)
      d = 0;
    else
      d = static_cast<std::uint16_t>(d + static_cast<int>(rng() % 9) - 4);
  }
  return m;
}

/// Shapes of constant disparity, apart from each other, placed at (ox, oy) in a w x h frame:
/// rectangles, ellipses, an L, a square spiral, a ring, a plus, lines, single pixels.
Map shapes_map(int w, int h, int ox, int oy) {
  cv::Mat img(h, w, CV_16U, cv::Scalar(0));
  const cv::Point o(ox, oy);
  const cv::Scalar v(400);
  cv::rectangle(img, cv::Rect(o + cv::Point(5, 5), cv::Size(20, 10)), v, cv::FILLED);
  cv::rectangle(img, cv::Rect(o + cv::Point(30, 5), cv::Size(3, 17)), v, cv::FILLED);
  cv::ellipse(img, o + cv::Point(60, 25), cv::Size(18, 8), 30, 0, 360, v, cv::FILLED, cv::LINE_4);
  cv::ellipse(img, o + cv::Point(110, 25), cv::Size(15, 9), 0, 0, 360, v, cv::FILLED, cv::LINE_4);
  cv::rectangle(img, cv::Rect(o + cv::Point(140, 5), cv::Size(6, 26)), v, cv::FILLED);
  cv::rectangle(img, cv::Rect(o + cv::Point(140, 26), cv::Size(21, 5)), v, cv::FILLED);
  const std::vector<cv::Point> spiral = {{10, 50}, {60, 50}, {60, 95}, {14, 95}, {14, 56},
                                         {54, 56}, {54, 89}, {20, 89}, {20, 62}, {48, 62},
                                         {48, 83}, {26, 83}, {26, 68}, {40, 68}};
  std::vector<cv::Point> shifted;
  for (const auto& p : spiral) shifted.push_back(p + o);
  cv::polylines(img, shifted, false, v, 1, cv::LINE_4);
  cv::circle(img, o + cv::Point(100, 130), 20, v, 2, cv::LINE_4);
  cv::rectangle(img, cv::Rect(o + cv::Point(150, 110), cv::Size(21, 3)), v, cv::FILLED);
  cv::rectangle(img, cv::Rect(o + cv::Point(159, 101), cv::Size(3, 21)), v, cv::FILLED);
  cv::line(img, o + cv::Point(75, 60), o + cv::Point(125, 60), v, 1, cv::LINE_4);
  cv::line(img, o + cv::Point(130, 45), o + cv::Point(130, 95), v, 1, cv::LINE_4);
  cv::line(img, o + cv::Point(140, 40), o + cv::Point(185, 90), v, 1, cv::LINE_4);
  for (const cv::Point p : {cv::Point(100, 100), cv::Point(5, 150), cv::Point(70, 75)})
    img.at<std::uint16_t>(p + o) = 400;
  img.at<std::uint16_t>(h - 1, w - 1) = 400;  // the frame's last pixel
  return from_mat(img);
}

/// CV_8U mask (255) of the pixels labelled k, in the whole frame (so cv::moments sees the same
/// coordinates as the reference).
cv::Mat object_mask(const LabellingReference& r, int w, int h, int k) {
  cv::Mat mask(h, w, CV_8U, cv::Scalar(0));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (r.labels[static_cast<std::size_t>(y) * w + x] == k) mask.at<std::uint8_t>(y, x) = 255;
  return mask;
}

Object make_object(std::uint32_t area, int x_min, int x_max, int y_min, int y_max, int d_min,
                   int d_max, int closest_x, int closest_y, int first_x, int first_y,
                   std::array<std::uint64_t, 9> m /* m10 m01 m20 m11 m02 m30 m21 m12 m03 */,
                   std::array<std::uint64_t, 2> sums /* sum_d sum_dd */) {
  const auto u16 = [](int v) { return static_cast<std::uint16_t>(v); };
  Object o;
  o.area = area;
  o.x_min = u16(x_min), o.x_max = u16(x_max), o.y_min = u16(y_min), o.y_max = u16(y_max);
  o.d_min = u16(d_min), o.d_max = u16(d_max);
  o.closest_x = u16(closest_x), o.closest_y = u16(closest_y);
  o.first_x = u16(first_x), o.first_y = u16(first_y);
  o.m10 = m[0], o.m01 = m[1], o.m20 = m[2], o.m11 = m[3], o.m02 = m[4];
  o.m30 = m[5], o.m21 = m[6], o.m12 = m[7], o.m03 = m[8];
  o.sum_d = sums[0], o.sum_dd = sums[1];
  return o;
}

std::vector<std::uint16_t> labels_of(const std::vector<std::vector<std::uint16_t>>& rows) {
  std::vector<std::uint16_t> out;
  for (const auto& r : rows) out.insert(out.end(), r.begin(), r.end());
  return out;
}

/// A constant-disparity map against cv::connectedComponentsWithStats (4-connectivity, SAUF,
/// which numbers components in raster order of their first pixel, as the reference does):
/// same labels pixel for pixel, same areas and boxes, and raw moments equal to cv::moments'.
void expect_same_as_opencv(const Map& m) {
  cv::Mat mask(m.height, m.width, CV_8U);
  for (int y = 0; y < m.height; ++y)
    for (int x = 0; x < m.width; ++x)
      mask.at<std::uint8_t>(y, x) = m.d[static_cast<std::size_t>(y) * m.width + x] ? 255 : 0;
  cv::Mat cc, stats, centroids;
  const int n =
      cv::connectedComponentsWithStats(mask, cc, stats, centroids, 4, CV_32S, cv::CCL_SAUF);
  const LabellingReference r = run(m);
  INFO(m.width << " x " << m.height << " map");
  REQUIRE(r.components == n - 1);
  REQUIRE(r.objects.size() == static_cast<std::size_t>(n - 1));
  int mismatches = 0;
  for (int y = 0; y < m.height; ++y)
    for (int x = 0; x < m.width; ++x)
      mismatches += r.labels[static_cast<std::size_t>(y) * m.width + x] != cc.at<int>(y, x);
  REQUIRE(mismatches == 0);
  for (int k = 1; k < n; ++k) {
    const Object& o = r.objects[k - 1];
    INFO("object " << k);
    CHECK(o.area == static_cast<std::uint32_t>(stats.at<int>(k, cv::CC_STAT_AREA)));
    CHECK(o.x_min == stats.at<int>(k, cv::CC_STAT_LEFT));
    CHECK(o.y_min == stats.at<int>(k, cv::CC_STAT_TOP));
    CHECK(o.x_max == stats.at<int>(k, cv::CC_STAT_LEFT) + stats.at<int>(k, cv::CC_STAT_WIDTH) - 1);
    CHECK(o.y_max == stats.at<int>(k, cv::CC_STAT_TOP) + stats.at<int>(k, cv::CC_STAT_HEIGHT) - 1);
    CHECK(cc.at<int>(o.first_y, o.first_x) == k);
    CHECK(o.d_min == m.d[static_cast<std::size_t>(o.first_y) * m.width + o.first_x]);
    // cv::moments scales binary tiles by a rounded 1/255, so its raw moments are a few ulps off.
    const cv::Moments cm = cv::moments(object_mask(r, m.width, m.height, k), true);
    const std::array<double, 10> cv_raw = {cm.m00, cm.m10, cm.m01, cm.m20, cm.m11,
                                           cm.m02, cm.m30, cm.m21, cm.m12, cm.m03};
    const std::array<std::uint64_t, 10> raw = {o.area, o.m10, o.m01, o.m20, o.m11,
                                               o.m02,  o.m30, o.m21, o.m12, o.m03};
    for (int i = 0; i < 10; ++i)
      CHECK(cv_raw[i] == Approx(static_cast<double>(raw[i])).epsilon(1e-12).margin(1e-9));
  }
}

// --- Hu moments against OpenCV ------------------------------------------------------------------
//
// Tolerance. hu_moments() forms the central moments exactly and rounds about once, so the
// difference from cv::HuMoments is OpenCV's own rounding error. That error is not relative to
// each value: cv::moments gets mu30 as m30 - cx (3 mu20 + cx m10), subtracting numbers of size
// m00 x^3 (x the object's distance from the origin) that agree in most of their digits, and a
// symmetric shape's h3 .. h7 (mathematically 0, or a tiny difference of products) are left as
// pure noise of that size. A tolerance relative to the object's largest |h_i| would not do:
// h1 ~ eta2 while h7 ~ eta3^4, so the two live at unrelated scales. Instead the test carries a
// bound on OpenCV's absolute error through OpenCV's own sequence of operations (running forward
// error analysis, Higham ch. 3): the raw moments start with (tiles + 8) u relative error (u =
// 2^-53: the rounded 1/255 binary scaling, the tile-shift sums and one rounding per tile added),
// then every +, -, * adds |a| err(b) + |b| err(a) + err(a) err(b) plus u |result|. Each value
// must then satisfy |ours - cv| <= max(1e-9 |cv|, 2 bound): the primary 1e-9 relative test
// wherever OpenCV carries 9 good digits, and OpenCV's own noise level where it does not, i.e.
// where the value is numerically zero at double precision. The factor 2 covers evaluating the
// bound at OpenCV's rounded rather than exact values; the largest difference seen here is 5 % of
// the bound, so the bound is loose but safe. Each object is checked twice: in the whole frame as
// the stage sees it, and cropped to its bounding box, where the coordinates, and so OpenCV's
// cancellation, are small and most values face the 1e-9 relative test.

struct Bounded {
  double v = 0, err = 0;  // a value and a bound on its absolute error
};
constexpr double kUnit = std::numeric_limits<double>::epsilon() / 2;
Bounded rounded(double v, double err) { return {v, err + kUnit * std::abs(v)}; }
Bounded operator+(Bounded a, Bounded b) { return rounded(a.v + b.v, a.err + b.err); }
Bounded operator-(Bounded a, Bounded b) { return rounded(a.v - b.v, a.err + b.err); }
Bounded operator*(Bounded a, Bounded b) {
  return rounded(a.v * b.v, std::abs(a.v) * b.err + std::abs(b.v) * a.err + a.err * b.err);
}
Bounded operator*(double c, Bounded a) { return rounded(c * a.v, std::abs(c) * a.err); }

/// Bounds on |cv::HuMoments(cv::moments(mask, true))[i] - exact h_i| for a mask whose pixels
/// meet `tiles` of OpenCV's 32 x 32 tiles and whose raw moments are `cm`'s (positive, and off
/// the exact ones by less than the bound itself), following OpenCV 4.6's completeMomentState and
/// HuMoments step for step.
std::array<double, 7> opencv_hu_error_bound(const cv::Moments& cm, int tiles) {
  const auto raw = [&](double v) { return Bounded{v, (tiles + 8) * kUnit * v}; };
  const Bounded m00 = raw(cm.m00), m10 = raw(cm.m10), m01 = raw(cm.m01), m20 = raw(cm.m20),
                m11 = raw(cm.m11), m02 = raw(cm.m02), m30 = raw(cm.m30), m21 = raw(cm.m21),
                m12 = raw(cm.m12), m03 = raw(cm.m03);
  const Bounded inv = rounded(1 / m00.v, m00.err / (m00.v * m00.v));
  const Bounded cx = m10 * inv, cy = m01 * inv;
  const Bounded mu20 = m20 - m10 * cx, mu11 = m11 - m10 * cy, mu02 = m02 - m01 * cy;
  const Bounded mu30 = m30 - cx * (3 * mu20 + cx * m10);
  const Bounded mu11x2 = mu11 + mu11;
  const Bounded mu21 = m21 - cx * (mu11x2 + cx * m01) - cy * mu20;
  const Bounded mu12 = m12 - cy * (mu11x2 + cy * m10) - cx * mu02;
  const Bounded mu03 = m03 - cy * (3 * mu02 + cy * m01);
  const double root = std::sqrt(inv.v);
  const Bounded inv_sqrt = rounded(root, inv.err / (2 * root));
  const Bounded s2 = inv * inv, s3 = s2 * inv_sqrt;
  const Bounded nu20 = mu20 * s2, nu11 = mu11 * s2, nu02 = mu02 * s2;
  const Bounded nu30 = mu30 * s3, nu21 = mu21 * s3, nu12 = mu12 * s3, nu03 = mu03 * s3;
  Bounded t0 = nu30 + nu12, t1 = nu21 + nu03;
  Bounded q0 = t0 * t0, q1 = t1 * t1;
  const Bounded n4 = 4 * nu11, s = nu20 + nu02, d = nu20 - nu02;
  std::array<Bounded, 7> hu;
  hu[0] = s;
  hu[1] = d * d + n4 * nu11;
  hu[3] = q0 + q1;
  hu[5] = d * (q0 - q1) + n4 * t0 * t1;
  t0 = t0 * (q0 - 3 * q1);
  t1 = t1 * (3 * q0 - q1);
  q0 = nu30 - 3 * nu12;
  q1 = 3 * nu21 - nu03;
  hu[2] = q0 * q0 + q1 * q1;
  hu[4] = q0 * t0 + q1 * t1;
  hu[6] = q1 * t0 - q0 * t1;
  std::array<double, 7> out;
  for (int i = 0; i < 7; ++i) out[i] = hu[i].err;
  return out;
}

struct HuTally {
  int relative = 0;  // values held to 1e-9 relative
  int noise = 0;     // values at OpenCV's noise level (numerically zero in double)
};

/// hu_moments() against cv::HuMoments(cv::moments(mask, true)) with the tolerance above; `tiles`
/// is the number of OpenCV's 32 x 32 tiles the mask's pixels may meet.
void expect_hu_on_mask(const std::array<double, 7>& ours, const cv::Mat& mask, int tiles,
                       HuTally& tally) {
  const cv::Moments cm = cv::moments(mask, true);
  double cv_hu[7];
  cv::HuMoments(cm, cv_hu);
  const auto bound = opencv_hu_error_bound(cm, tiles);
  for (int i = 0; i < 7; ++i) {
    const double rel = 1e-9 * std::abs(cv_hu[i]), noise = 2 * bound[i];
    (rel >= noise ? tally.relative : tally.noise) += 1;
    INFO("h" << i + 1 << ": ours " << ours[i] << ", OpenCV " << cv_hu[i] << ", OpenCV's error "
             << "bound " << bound[i]);
    CHECK(std::abs(ours[i] - cv_hu[i]) <= std::max(rel, noise));
  }
}

/// Every object of `m`: hu_moments() against cv::HuMoments on its mask, both in the whole frame
/// (as the stage sees it) and cropped to its bounding box (Hu's invariants do not move with the
/// object, but OpenCV's cancellation noise shrinks with the coordinates, so more values face
/// the 1e-9 relative test); central_moments() against exact pixel sums.
void expect_hu_as_opencv(const Map& m, int floor, int min_area, HuTally& frame_tally,
                         HuTally& box_tally) {
  const LabellingReference r = run(m, floor, min_area);
  REQUIRE(!r.objects.empty());
  for (std::size_t k = 1; k <= r.objects.size(); ++k) {
    const Object& o = r.objects[k - 1];
    const cv::Mat mask = object_mask(r, m.width, m.height, static_cast<int>(k));
    const auto ours = hu_moments(o);
    INFO("object " << k << " of " << r.objects.size() << ": area " << o.area << ", box (" << o.x_min
                   << ", " << o.y_min << ") - (" << o.x_max << ", " << o.y_max << ")");
    const int box_w = o.x_max - o.x_min + 1, box_h = o.y_max - o.y_min + 1;
    {
      INFO("in the whole frame");
      expect_hu_on_mask(ours, mask,
                        (o.x_max / 32 - o.x_min / 32 + 1) * (o.y_max / 32 - o.y_min / 32 + 1),
                        frame_tally);
    }
    {
      INFO("cropped to the bounding box");
      expect_hu_on_mask(ours, mask(cv::Rect(o.x_min, o.y_min, box_w, box_h)).clone(),
                        ((box_w + 31) / 32) * ((box_h + 31) / 32), box_tally);
    }

    // Exact central moments: sum (n x - m10)^p (n y - m01)^q = n^(p+q) mu_pq, in integers.
    const i128 n = o.area, m10 = o.m10, m01 = o.m01;
    std::array<i128, 7> sums{};
    for (int y = o.y_min; y <= o.y_max; ++y)
      for (int x = o.x_min; x <= o.x_max; ++x) {
        if (mask.at<std::uint8_t>(y, x) == 0) continue;
        const i128 a = n * x - m10, b = n * y - m01;
        sums[0] += a * a, sums[1] += a * b, sums[2] += b * b;
        sums[3] += a * a * a, sums[4] += a * a * b, sums[5] += a * b * b, sums[6] += b * b * b;
      }
    const auto mu = central_moments(o);
    for (int i = 0; i < 7; ++i) {
      const long double scale =
          i < 3 ? static_cast<long double>(n * n) : static_cast<long double>(n * n * n);
      const double exact = static_cast<double>(static_cast<long double>(sums[i]) / scale);
      INFO("central moment " << i << ": " << mu[i] << " vs exact " << exact);
      if (sums[i] == 0)
        CHECK(mu[i] == 0.0);
      else  // two roundings (long double, then double) of the same rational: within 2 ulp
        CHECK(std::abs(mu[i] - exact) <= 4 * kUnit * std::abs(exact));
    }
  }
}

// --- the partition -----------------------------------------------------------------------------

TEST_CASE("constant-disparity maps: the same partition as cv::connectedComponentsWithStats",
          "[labelling][ref]") {
  SECTION("random masks of several densities and sizes") {
    std::uint32_t seed = 1;
    for (const auto& [w, h] : std::vector<std::pair<int, int>>{
             {1, 1}, {1, 17}, {17, 1}, {2, 2}, {37, 23}, {64, 48}, {161, 97}})
      for (const int permille : {0, 50, 300, 500, 593, 650, 800, 1000})
        expect_same_as_opencv(random_binary_map(w, h, permille, seed++));
  }
  SECTION("shapes: spiral, ring, L, lines, single pixels, the frame's last pixel") {
    expect_same_as_opencv(shapes_map(200, 160, 0, 0));
  }
  SECTION("a checkerboard: every pixel is its own component under 4-connectivity") {
    Map m(33, 21);
    for (int y = 0; y < m.height; ++y)
      for (int x = 0; x < m.width; ++x) m.at(x, y) = (x + y) % 2 ? 0 : 160;
    expect_same_as_opencv(m);
    CHECK(run(m).components == (33 * 21 + 1) / 2);
  }
  SECTION("combs and U shapes that join only at their last row") {
    Map m(40, 12);
    for (int x = 0; x < 40; x += 2)
      for (int y = 0; y < 11; ++y) m.at(x, y) = 160;
    for (int x = 0; x < 40; ++x) m.at(x, 11) = 160;
    expect_same_as_opencv(m);
    const LabellingReference r = run(m);
    REQUIRE(r.objects.size() == 1);
    CHECK(r.objects[0].area == 20 * 11 + 40);
  }
}

TEST_CASE("the join rule takes the later pixel's disparity as the reference", "[labelling][ref]") {
  // 10 |99 - 90| = 90: not below 90, but below 99.
  REQUIRE_FALSE(joins(90, 99));
  REQUIRE(joins(99, 90));

  SECTION("left neighbour: 99 then 90 stays apart, 90 then 99 joins") {
    const LabellingReference apart = run(from_rows({{99, 90}}));
    CHECK(apart.components == 2);
    CHECK(apart.labels == labels_of({{1, 2}}));
    REQUIRE(apart.objects.size() == 2);
    CHECK(apart.objects[0] == make_object(1, 0, 0, 0, 0, 99, 99, 0, 0, 0, 0, {}, {99, 9801}));
    CHECK(apart.objects[1] ==
          make_object(1, 1, 1, 0, 0, 90, 90, 1, 0, 1, 0, {1, 0, 1, 0, 0, 1, 0, 0, 0}, {90, 8100}));
    const LabellingReference joined = run(from_rows({{90, 99}}));
    CHECK(joined.labels == labels_of({{1, 1}}));
    REQUIRE(joined.objects.size() == 1);
    CHECK(joined.objects[0] ==
          make_object(2, 0, 1, 0, 0, 90, 99, 1, 0, 0, 0, {1, 0, 1, 0, 0, 1, 0, 0, 0},
                      {189, 17901}));
  }
  SECTION("up neighbour: the same") {
    const LabellingReference apart = run(from_rows({{99}, {90}}));
    CHECK(apart.labels == labels_of({{1}, {2}}));
    REQUIRE(apart.objects.size() == 2);
    CHECK(apart.objects[1] ==
          make_object(1, 0, 0, 1, 1, 90, 90, 0, 1, 0, 1, {0, 1, 0, 0, 1, 0, 0, 0, 1}, {90, 8100}));
    const LabellingReference joined = run(from_rows({{90}, {99}}));
    CHECK(joined.labels == labels_of({{1}, {1}}));
    REQUIRE(joined.objects.size() == 1);
    CHECK(joined.objects[0] ==
          make_object(2, 0, 0, 0, 1, 90, 99, 0, 1, 0, 0, {0, 1, 0, 0, 1, 0, 0, 0, 1},
                      {189, 17901}));
  }
  SECTION("a U: the right arm joins the left through the bottom row, or does not") {
    // (1,1)-(2,1): 10 |100 - 99| = 10 < 99 joins; (2,0)-(2,1): later 99, earlier 90 joins.
    const LabellingReference u = run(from_rows({{100, 0, 90}, {100, 100, 99}}));
    CHECK(u.components == 1);
    CHECK(u.labels == labels_of({{1, 0, 1}, {1, 1, 1}}));
    REQUIRE(u.objects.size() == 1);
    // Pixels (0,0) (2,0) (0,1) (1,1) (2,1).
    CHECK(u.objects[0] ==
          make_object(5, 0, 2, 0, 1, 90, 100, 0, 0, 0, 0, {5, 3, 9, 3, 3, 17, 5, 3, 3},
                      {489, 47901}));
    // Swapped: later 90 against 99 (10 * 9 = 90, not < 90) and later 90 against 100: apart.
    const LabellingReference split = run(from_rows({{100, 0, 99}, {100, 100, 90}}));
    CHECK(split.components == 3);
    CHECK(split.labels == labels_of({{1, 0, 2}, {1, 1, 3}}));
    REQUIRE(split.objects.size() == 3);
    CHECK(split.objects[0] ==
          make_object(3, 0, 1, 0, 1, 100, 100, 0, 0, 0, 0, {1, 2, 1, 1, 2, 1, 1, 1, 2},
                      {300, 30000}));
    CHECK(split.objects[1] ==
          make_object(1, 2, 2, 0, 0, 99, 99, 2, 0, 2, 0, {2, 0, 4, 0, 0, 8, 0, 0, 0}, {99, 9801}));
    CHECK(split.objects[2] ==
          make_object(1, 2, 2, 1, 1, 90, 90, 2, 1, 2, 1, {2, 1, 4, 2, 1, 8, 4, 2, 1}, {90, 8100}));
  }
  SECTION("joins chain: 100 - 91 - 83 is one object though 83 and 100 would not join") {
    REQUIRE_FALSE(joins(83, 100));
    const LabellingReference r = run(from_rows({{100, 91, 83}}));
    REQUIRE(r.objects.size() == 1);
    CHECK(r.objects[0].d_min == 83);
    CHECK(r.objects[0].d_max == 100);
    CHECK(run(from_rows({{100, 0, 83}})).components == 2);
  }
}

TEST_CASE("random disparities: every joined pair is inside one object, every cut is a real cut",
          "[labelling][ref]") {
  // The definition checked edge by edge: neighbours that join share a label; neighbours in two
  // different objects do not join. (Same-label neighbours that do not join are allowed: they
  // may be connected around.)
  for (std::uint32_t seed = 1; seed <= 6; ++seed) {
    const Map m = random_disparity_map(90, 70, seed);
    const LabellingReference r = run(m);
    int cuts = 0;
    for (int y = 0; y < m.height; ++y)
      for (int x = 0; x < m.width; ++x) {
        const std::size_t i = static_cast<std::size_t>(y) * m.width + x;
        CHECK((r.labels[i] == 0) == (m.d[i] == 0));
        for (const std::size_t p : {x > 0 ? i - 1 : i, y > 0 ? i - m.width : i}) {
          if (p == i || m.d[p] == 0 || m.d[i] == 0) continue;
          if (joins(m.d[i], m.d[p])) CHECK(r.labels[p] == r.labels[i]);
          cuts += r.labels[p] != r.labels[i];
        }
      }
    INFO("seed " << seed);
    CHECK(cuts > 0);  // the map exercises the rule, not only validity
    CHECK(r.components > 5);
  }
}

// --- validity, size filter, descriptors, errors ------------------------------------------------

TEST_CASE("validity: zero, the sign bit and the floor", "[labelling][ref]") {
  // 0x8000 and 0xFFF0 are negative as int16 (an invalid code); 51 - 50 - 51 joins (10 < 50).
  const Map m = from_rows({{0x8000, 51, 50, 51, 0xFFF0, 60, 0, 70, 0, 0x7FFF}});
  CHECK(run(m, 0).labels == labels_of({{0, 1, 1, 1, 0, 2, 0, 3, 0, 4}}));
  CHECK(run(m, 50).labels == labels_of({{0, 1, 0, 2, 0, 3, 0, 4, 0, 5}}));
  CHECK(run(m, 60).labels == labels_of({{0, 0, 0, 0, 0, 0, 0, 1, 0, 2}}));
  CHECK(run(m, 0x7FFF).components == 0);
  // A negative floor does not make zero or negative codes valid.
  CHECK(run(m, -5).labels == run(m, 0).labels);
}

TEST_CASE("min_area drops small objects, renumbers the rest, counts all", "[labelling][ref]") {
  // Areas in raster order of first pixel: 1, 3, 2, 5.
  const Map m = from_rows({{160, 0, 160, 160, 0, 160},
                           {0, 0, 160, 0, 0, 160},
                           {160, 160, 0, 160, 160, 160},
                           {0, 0, 0, 0, 0, 160}});
  const LabellingReference all = run(m, 0, 1);
  CHECK(
      all.labels ==
      labels_of({{1, 0, 2, 2, 0, 3}, {0, 0, 2, 0, 0, 3}, {4, 4, 0, 3, 3, 3}, {0, 0, 0, 0, 0, 3}}));
  REQUIRE(all.objects.size() == 4);
  CHECK(all.objects[1].area == 3);
  CHECK(all.objects[2].area == 6);
  CHECK(all.objects[3].area == 2);
  CHECK(run(m, 0, 0).labels == all.labels);

  const LabellingReference big = run(m, 0, 3);
  CHECK(big.components == 4);
  CHECK(
      big.labels ==
      labels_of({{0, 0, 1, 1, 0, 2}, {0, 0, 1, 0, 0, 2}, {0, 0, 0, 2, 2, 2}, {0, 0, 0, 0, 0, 2}}));
  REQUIRE(big.objects.size() == 2);
  CHECK(big.objects[0] == all.objects[1]);
  CHECK(big.objects[1] == all.objects[2]);

  const LabellingReference none = run(m, 0, 7);
  CHECK(none.components == 4);
  CHECK(none.objects.empty());
  CHECK(std::all_of(none.labels.begin(), none.labels.end(), [](auto l) { return l == 0; }));
}

TEST_CASE("descriptors and moments of a hand-computed object", "[labelling][ref]") {
  // An L of pixels (1,0) (1,1) (1,2) (2,2); d_max 170 twice: the closest point is the first.
  const LabellingReference r = run(from_rows({{0, 160, 0, 0}, {0, 170, 0, 0}, {0, 170, 165, 0}}));
  REQUIRE(r.objects.size() == 1);
  const Object& o = r.objects[0];
  // m10 = 1+1+1+2, m01 = 0+1+2+2, m20 = 1+1+1+4, m11 = 0+1+2+4, m02 = 0+1+4+4,
  // m30 = 1+1+1+8, m21 = 0+1+2+8, m12 = 0+1+4+8, m03 = 0+1+8+8; sum d = 160+170+170+165,
  // sum d^2 = 25600+28900+28900+27225.
  CHECK(o == make_object(4, 1, 2, 0, 2, 160, 170, 1, 1, 1, 0, {5, 5, 7, 7, 9, 11, 11, 13, 17},
                         {665, 110625}));
  // About the centroid (5/4, 5/4): dx = -1/4 -1/4 -1/4 3/4, dy = -5/4 -1/4 3/4 3/4.
  CHECK(central_moments(o) ==
        std::array<double, 7>{0.75, 0.75, 2.75, 0.375, 0.375, -0.125, -1.125});
  // eta2 = mu2 / 16: h1 = (0.75 + 2.75) / 16, h2 = ((0.75 - 2.75) / 16)^2 + 4 (0.75 / 16)^2.
  const auto hu = hu_moments(o);
  CHECK(hu[0] == 0.21875);
  CHECK(hu[1] == 0.0244140625);
}

TEST_CASE("Hu moments of a single pixel and of symmetric shapes", "[labelling][ref]") {
  SECTION("a single pixel: m00 = 1, every central moment and invariant 0") {
    for (const auto& [x, y] : std::vector<std::pair<int, int>>{{0, 0}, {7, 3}, {2047, 1023}}) {
      Map m(x + 1, y + 1);
      m.at(x, y) = 16;
      const LabellingReference r = run(m);
      REQUIRE(r.objects.size() == 1);
      CHECK(r.objects[0].area == 1);
      CHECK(central_moments(r.objects[0]) == std::array<double, 7>{});
      CHECK(hu_moments(r.objects[0]) == std::array<double, 7>{});
    }
  }
  SECTION("a rectangle far from the origin: exact zeros where symmetry cancels") {
    Map m(1000, 700);
    for (int y = 650; y < 661; ++y)
      for (int x = 900; x < 917; ++x) m.at(x, y) = 300;
    const LabellingReference r = run(m);
    REQUIRE(r.objects.size() == 1);
    const auto mu = central_moments(r.objects[0]);
    CHECK(mu[0] == Approx(11.0 * (17 * 17 - 1) / 12 * 17));  // 11 rows of n (n^2 - 1) / 12
    CHECK(mu[1] == 0.0);
    for (int i = 3; i < 7; ++i) CHECK(mu[i] == 0.0);
    const auto hu = hu_moments(r.objects[0]);
    for (int i = 2; i < 7; ++i) CHECK(hu[i] == 0.0);
  }
  SECTION("area 0 gives zeros, as OpenCV's empty moments") {
    CHECK(hu_moments(Object{}) == std::array<double, 7>{});
  }
}

TEST_CASE("Hu moments equal cv::HuMoments on every object's mask", "[labelling][ref]") {
  HuTally frame, box;
  SECTION("shapes near the origin and far from it") {
    expect_hu_as_opencv(shapes_map(200, 160, 0, 0), 0, 1, frame, box);
    expect_hu_as_opencv(shapes_map(1024, 768, 820, 600), 0, 1, frame, box);
  }
  SECTION("random masks near the percolation threshold (large ragged components)") {
    for (std::uint32_t seed = 1; seed <= 3; ++seed)
      expect_hu_as_opencv(random_binary_map(120, 90, 593, 100 + seed), 0, 1, frame, box);
  }
  SECTION("random disparity maps cut by the join rule") {
    for (std::uint32_t seed = 1; seed <= 4; ++seed)
      expect_hu_as_opencv(random_disparity_map(160, 120, 200 + seed), 0, 1, frame, box);
  }
  // On cropped masks the relative test is the rule (about 70 % of the shapes' values, 90 % of
  // the random objects'); the rest are single pixels, pairs and symmetric shapes' zeros.
  INFO("whole frame: " << frame.relative << " values held to 1e-9 relative, " << frame.noise
                       << " numerically zero; cropped: " << box.relative << " / " << box.noise);
  CHECK(box.relative > box.noise);
}

TEST_CASE("bad arguments are refused", "[labelling][ref]") {
  const std::vector<std::uint16_t> d(4, 16);
  const LabellingConfig cfg;
  CHECK_THROWS_AS(labelling_reference(nullptr, 2, 2, cfg), std::invalid_argument);
  CHECK_THROWS_AS(labelling_reference(d.data(), 0, 2, cfg), std::invalid_argument);
  CHECK_THROWS_AS(labelling_reference(d.data(), 2, 0, cfg), std::invalid_argument);
  CHECK_THROWS_AS(labelling_reference(d.data(), -1, 2, cfg), std::invalid_argument);
}

// --- real data ---------------------------------------------------------------------------------

TEST_CASE("Tsukuba ground truth: plausible objects, labels matching areas", "[labelling][ref]") {
  // 8-bit disparity x 16, i.e. already Q11.4; 0 marks unknown pixels at the border.
  const cv::Mat gt = scw::host::io::read_tsukuba_truth(SCW_DATA_DIR "/tsukuba");
  const Map m = from_mat(gt);
  const LabellingReference all = run(m, 0, 1);
  const LabellingReference big = run(m, 0, 50);
  INFO(all.components << " components, " << big.objects.size() << " of 50 px or more");
  CHECK(big.components == all.components);
  REQUIRE(all.objects.size() == static_cast<std::size_t>(all.components));
  // 7 disparity levels (5 .. 14); the background (5) is cut into pieces by what stands before
  // it: 37 components, 23 of 50 px or more.
  CHECK(all.components >= 10);
  CHECK(all.components <= 200);
  CHECK(big.objects.size() >= 5);
  CHECK(big.objects.size() <= 60);
  const auto largest =
      std::max_element(all.objects.begin(), all.objects.end(),
                       [](const Object& a, const Object& b) { return a.area < b.area; });
  CHECK(largest->d_max == 5 * 16);  // the back wall
  CHECK(largest->area > 30000);
  CHECK(std::any_of(big.objects.begin(), big.objects.end(),  // the lamp, nearest
                    [](const Object& o) { return o.d_max == 14 * 16 && o.area > 1000; }));
  // One level (16) apart joins only when the later pixel exceeds 160 (disparity 11 or more):
  // every object up to 10 holds a single level.
  for (const Object& o : all.objects)
    if (o.d_max <= 160) CHECK(o.d_min == o.d_max);
  for (const LabellingReference* r : {&all, &big}) {
    std::vector<std::uint32_t> count(r->objects.size() + 1, 0);
    for (const auto l : r->labels) ++count[l];
    for (std::size_t k = 1; k <= r->objects.size(); ++k) CHECK(count[k] == r->objects[k - 1].area);
  }
  // The filtered run keeps exactly the big objects of the full run, in the same order.
  std::vector<Object> kept;
  for (const Object& o : all.objects)
    if (o.area >= 50) kept.push_back(o);
  CHECK(kept == big.objects);
  HuTally frame, box;
  expect_hu_as_opencv(m, 0, 50, frame, box);
  INFO("whole frame: " << frame.relative << " values held to 1e-9 relative, " << frame.noise
                       << " numerically zero; cropped: " << box.relative << " / " << box.noise);
  CHECK(box.relative > box.noise);
}

}  // namespace
