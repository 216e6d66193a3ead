// SPDX-License-Identifier: Apache-2.0
// The direct disparity reference: hand-checkable thesis-mode cases and opencv mode against
// cv::StereoBM on Tsukuba (docs/disparity.md).
#include <algorithm>
#include <catch2/catch.hpp>
#include <cstdint>
#include <cstdlib>
#include <opencv2/calib3d.hpp>
#include <opencv2/core.hpp>
#include <opencv2/core/utility.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <random>
#include <string>
#include <vector>

#include "hls/disparity/disparity_params.hpp"
#include "host/reference/disparity_ref.hpp"
#include "host/reference/stereo_bm.hpp"

namespace {

using scw::hls::disparity::DisparityConfig;
using scw::hls::disparity::invalid_code;
using scw::hls::disparity::opencv_mode;
using scw::hls::disparity::thesis_mode;
using scw::reference::disparity_reference;
using scw::reference::prefilter_xsobel_reference;
using scw::reference::sad_reference;
using scw::reference::subpixel_reference;

struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> px;
  std::uint8_t& at(int x, int y) { return px[static_cast<std::size_t>(y) * width + x]; }
};

Image random_image(int width, int height, std::uint32_t seed) {
  std::mt19937 rng(seed);
  Image img{width, height, std::vector<std::uint8_t>(static_cast<std::size_t>(width) * height)};
  for (auto& p : img.px) p = static_cast<std::uint8_t>(rng() & 0xff);
  return img;
}

/// A left view of `right` at disparity `shift`: L(u, v) = R(u - shift, v); the first `shift`
/// columns (seen by the left camera only) are fresh noise.
Image shifted_left(const Image& right, int shift, std::uint32_t seed) {
  Image l = random_image(right.width, right.height, seed);
  for (int v = 0; v < right.height; ++v)
    for (int u = shift; u < right.width; ++u)
      l.px[static_cast<std::size_t>(v) * right.width + u] =
          right.px[static_cast<std::size_t>(v) * right.width + u - shift];
  return l;
}

std::int16_t value(const std::vector<std::uint16_t>& d, int width, int u, int v) {
  return static_cast<std::int16_t>(d[static_cast<std::size_t>(v) * width + u]);
}

std::vector<std::uint16_t> run(const Image& l, const Image& r, int n, int num_disp,
                               const DisparityConfig& cfg) {
  return disparity_reference(l.px.data(), r.px.data(), l.width, l.height, n, num_disp, cfg);
}

// --- thesis mode: hand-checkable cases --------------------------------------------------------

TEST_CASE("a shifted random texture gives exactly the shift on the whole valid region",
          "[disparity][ref]") {
  constexpr int kW = 48, kH = 20, kN = 5, kR = kN / 2;
  for (const int dmin : {0, 3}) {
    for (const int shift : {dmin, dmin + 4, dmin + 7}) {
      const Image r = random_image(kW, kH, 11u + static_cast<std::uint32_t>(shift));
      const Image l = shifted_left(r, shift, 99u);
      const auto cfg = thesis_mode(kW, kH, dmin);
      const auto d = run(l, r, kN, 8, cfg);
      INFO("dmin " << dmin << ", shift " << shift);
      for (int v = kR; v < kH - kR; ++v)
        for (int u = dmin + 7 + kR; u < kW - kR; ++u) REQUIRE(value(d, kW, u, v) == shift * 16);
    }
  }
}

TEST_CASE("ties pick the largest d, as cv::StereoBM", "[disparity][ref]") {
  constexpr int kW = 40, kH = 12, kN = 3;
  SECTION("a flat pair: every candidate costs 0, so d = dmin + 5, the last of 6") {
    Image l{kW, kH, std::vector<std::uint8_t>(kW * kH, 77)};
    const auto d = run(l, l, kN, 6, thesis_mode(kW, kH, 2));
    CHECK(value(d, kW, 20, 5) == 7 * 16);
    CHECK(value(d, kW, kW - 2, kH - 2) == 7 * 16);
  }
  SECTION("a texture of period 4 matches at shift 1 and 5: d = 5") {
    Image r{kW, kH, std::vector<std::uint8_t>(kW * kH)};
    const std::uint8_t period[4] = {10, 200, 40, 130};
    for (int v = 0; v < kH; ++v)
      for (int u = 0; u < kW; ++u) r.at(u, v) = static_cast<std::uint8_t>(period[u % 4] + v);
    const Image l = shifted_left(r, 1, 5u);
    const auto d = run(l, r, kN, 8, thesis_mode(kW, kH, 0));
    for (int u = 8; u < kW - 1; ++u) REQUIRE(value(d, kW, u, 5) == 5 * 16);
    // With the uniqueness rule on, the same tie (|5 - 1| > 1, SAD 0 <= 0) rejects.
    DisparityConfig unique = thesis_mode(kW, kH, 0);
    unique.uniqueness_ratio = 1;
    unique.opencv_invalid = true;
    const auto du = run(l, r, kN, 8, unique);
    CHECK(value(du, kW, 20, 5) == -16);
  }
}

TEST_CASE("the valid region: r <= v < H - r and DMax + r <= u < W - r", "[disparity][ref]") {
  constexpr int kW = 40, kH = 16, kN = 5, kR = kN / 2, kNumDisp = 6;
  const Image r = random_image(kW, kH, 3u);
  const Image l = shifted_left(r, 5, 4u);
  for (const int dmin : {0, 2}) {
    DisparityConfig cfg = thesis_mode(kW, kH, dmin);
    cfg.opencv_invalid = true;  // invalid (dmin - 1) * 16, distinct from every candidate
    const std::int16_t inv = static_cast<std::int16_t>((dmin - 1) * 16);
    const int dmax = dmin + kNumDisp - 1;
    const auto d = run(l, r, kN, kNumDisp, cfg);
    INFO("dmin " << dmin);
    for (int v = 0; v < kH; ++v)
      for (int u = 0; u < kW; ++u) {
        const bool inside = v >= kR && v < kH - kR && u >= dmax + kR && u < kW - kR;
        INFO("u " << u << ", v " << v);
        if (inside)
          REQUIRE(value(d, kW, u, v) == 5 * 16);
        else
          REQUIRE(value(d, kW, u, v) == inv);
      }
  }
  // Thesis mode's invalid code is 0, the same as d = 0.
  const auto d0 = run(l, r, kN, kNumDisp, thesis_mode(kW, kH, 0));
  CHECK(value(d0, kW, 0, 0) == 0);
  CHECK(value(d0, kW, kNumDisp - 1 + kR, kR) == 5 * 16);
}

TEST_CASE("sad_reference is eq. 2.15", "[disparity][ref]") {
  // 3 x 3 window at (u, v) = (3, 1), d = 2: left columns 2..4, right columns 0..2.
  Image l{6,
          3,
          {0, 0, 10, 20, 30, 0,  //
           0, 0, 11, 21, 31, 0,  //
           0, 0, 12, 22, 32, 0}};
  Image r{6,
          3,
          {9, 20, 33, 0, 0, 0,   //
           11, 25, 31, 0, 0, 0,  //
           12, 22, 0, 0, 0, 0}};
  // |10-9| + |20-20| + |30-33| + |11-11| + |21-25| + |31-31| + |12-12| + |22-22| + |32-0|
  CHECK(sad_reference(l.px.data(), r.px.data(), 6, 3, 1, 2, 3) ==
        1 + 0 + 3 + 0 + 4 + 0 + 0 + 0 + 32);
}

TEST_CASE("the SAD limit rejects min SAD > limit", "[disparity][ref]") {
  constexpr int kW = 24, kH = 9, kN = 3;
  const Image l{kW, kH, std::vector<std::uint8_t>(kW * kH, 10)};
  const Image r{kW, kH, std::vector<std::uint8_t>(kW * kH, 12)};  // every SAD is 9 * 2 = 18
  DisparityConfig cfg = thesis_mode(kW, kH, 1);
  cfg.sad_limit = 18;
  CHECK(value(run(l, r, kN, 4, cfg), kW, 10, 4) == 4 * 16);  // all tied: the largest d
  cfg.sad_limit = 17;
  CHECK(value(run(l, r, kN, 4, cfg), kW, 10, 4) == 0);
}

TEST_CASE("the texture rule: sum |prefiltered L - cap| < threshold rejects", "[disparity][ref]") {
  constexpr int kW = 32, kH = 12, kN = 5;
  const Image flat{kW, kH, std::vector<std::uint8_t>(kW * kH, 90)};  // prefiltered: all cap
  const Image r = random_image(kW, kH, 8u);
  const Image l = shifted_left(r, 3, 9u);
  DisparityConfig cfg = opencv_mode(kW, kH, 0, 31, 1, 0);
  cfg.subpixel = false;
  CHECK(value(run(flat, flat, kN, 8, cfg), kW, 20, 6) == -16);
  CHECK(value(run(l, r, kN, 8, cfg), kW, 20, 6) == 3 * 16);
  cfg.texture_threshold = 0;
  CHECK(value(run(flat, flat, kN, 8, cfg), kW, 20, 6) == 7 * 16);  // tie over all d: d = 7
}

TEST_CASE("the x-Sobel prefilter by hand", "[disparity][ref]") {
  // A ramp 3x: g = 6 on every row, sum 24 (< cap 31), out 55; a steep ramp 20x saturates at 62.
  for (const int h : {4, 5}) {
    Image ramp{6, h, std::vector<std::uint8_t>(6 * h)}, steep = ramp;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < 6; ++x) {
        ramp.at(x, y) = static_cast<std::uint8_t>(3 * x);
        steep.at(x, y) = static_cast<std::uint8_t>(20 * x);
      }
    const auto a = prefilter_xsobel_reference(ramp.px.data(), 6, h, 31);
    const auto b = prefilter_xsobel_reference(steep.px.data(), 6, h, 31);
    INFO("H = " << h);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < 6; ++x) {
        const bool border = x == 0 || x == 5 || (h % 2 == 1 && y == h - 1);
        REQUIRE(int{a[static_cast<std::size_t>(y) * 6 + x]} == (border ? 31 : 55));
        REQUIRE(int{b[static_cast<std::size_t>(y) * 6 + x]} == (border ? 31 : 62));
      }
  }
  // Rows -1 and H reflect to 1 and H - 2: one bright column step on row 1 only.
  Image step{5, 4, std::vector<std::uint8_t>(20, 0)};
  step.at(3, 1) = 4;  // g(2, 1) = +4, g(4, 1) = -4 (x = 4 is the border column)
  const auto s = prefilter_xsobel_reference(step.px.data(), 5, 4, 31);
  CHECK(int{s[0 * 5 + 2]} == 31 + 4 + 4);  // row 0: g(row -1 = row 1) + 2 g(row 0) + g(row 1)
  CHECK(int{s[1 * 5 + 2]} == 31 + 8);      // row 1: 2 g(row 1)
  CHECK(int{s[2 * 5 + 2]} == 31 + 4);      // row 2: g(row 1)
  CHECK(int{s[3 * 5 + 2]} == 31);          // row 3: rows 2, 3, 2
}

TEST_CASE("the sub-pixel value, OpenCV's rounding", "[disparity][ref]") {
  CHECK(subpixel_reference(5, 20, 4, 20) == 80);     // symmetric: no fraction
  CHECK(subpixel_reference(5, 4, 4, 20) == 80 - 8);  // tie with d - 1: frac -128 -> -8
  CHECK(subpixel_reference(5, 20, 4, 4) == 80 + 8);  // tie with d + 1: frac +128 -> +8
  CHECK(subpixel_reference(5, 10, 4, 20) == 75);     // frac -80: (1280 - 80 + 15) >> 4
  CHECK(subpixel_reference(-1, 10, 4, 20) == -21);   // floor(-321 / 16)
  CHECK(subpixel_reference(2, 15, 0, 17) == 32);     // frac trunc(-512/34) = -15, not -16
  CHECK(subpixel_reference(3, 7, 7, 7) == 48);       // den 0: no fraction
  // In the image: a winner at either end of the range gets no fraction.
  constexpr int kW = 40, kH = 9, kN = 3;
  const Image r = random_image(kW, kH, 21u);
  DisparityConfig cfg = opencv_mode(kW, kH, 2, 31, 0, 0);
  for (const int shift : {2, 9}) {
    const Image l = shifted_left(r, shift, 22u);
    CHECK(value(run(l, r, kN, 8, cfg), kW, 20, 4) == shift * 16);
  }
}

// --- opencv mode against cv::StereoBM ---------------------------------------------------------

Image load_grey(const std::string& path) {
  cv::Mat m = cv::imread(path, cv::IMREAD_COLOR);
  REQUIRE(!m.empty());
  cv::cvtColor(m, m, cv::COLOR_BGR2GRAY);
  Image img{m.cols, m.rows, {}};
  img.px.assign(m.begin<std::uint8_t>(), m.end<std::uint8_t>());
  return img;
}

std::vector<std::uint16_t> stereo_bm(const Image& l, const Image& r, int n, int num_disp,
                                     const DisparityConfig& cfg, bool optimized) {
  return scw::reference::stereo_bm(l.px.data(), r.px.data(), l.width, l.height, n, num_disp, cfg,
                                   optimized);
}

TEST_CASE("opencv mode equals cv::StereoBM on Tsukuba, SAD ties included", "[disparity][ref]") {
  const Image l = load_grey(std::string(SCW_DATA_DIR) + "/tsukuba/scene1.row3.col3.ppm");
  const Image r = load_grey(std::string(SCW_DATA_DIR) + "/tsukuba/scene1.row3.col4.ppm");
  constexpr int kNumDisp = 16;
  struct Case {
    int n, dmin, cap;
  };
  // cap 63 takes StereoBM's 32-bit path (useShorts() is cap <= 31 && N <= 21), the rest its
  // 16-bit SIMD path; setUseOptimized does not switch between them in OpenCV 4.6.
  const Case cases[] = {{5, 0, 31}, {9, 0, 31}, {15, 0, 31}, {21, 0, 31}, {9, 0, 63}, {9, 4, 31}};
  for (const Case& c : cases)
    for (const bool optimized : {true, false}) {
      const DisparityConfig cfg = opencv_mode(l.width, l.height, c.dmin, c.cap);
      const auto ref = run(l, r, c.n, kNumDisp, cfg);
      const auto cv = stereo_bm(l, r, c.n, kNumDisp, cfg, optimized);
      const auto pl = prefilter_xsobel_reference(l.px.data(), l.width, l.height, c.cap);
      const auto pr = prefilter_xsobel_reference(r.px.data(), r.width, r.height, c.cap);
      const int rad = c.n / 2, dmax = c.dmin + kNumDisp - 1;
      long region = 0, same = 0, ties = 0, outside_diff = 0;
      for (int v = 0; v < l.height; ++v)
        for (int u = 0; u < l.width; ++u) {
          const std::size_t i = static_cast<std::size_t>(v) * l.width + u;
          if (v < rad || v >= l.height - rad || u < dmax + rad || u >= l.width - rad) {
            // StereoBM computes columns up to W + dmin - 1 and, for dmin > 0, its last valid
            // row spills the dmin columns past the row end into row H - r (columns 0..dmin-1).
            const bool spill = c.dmin > 0 && v == l.height - rad && u < c.dmin;
            outside_diff += ref[i] != cv[i] && !spill;
            continue;
          }
          ++region;
          same += ref[i] == cv[i];
          // Pixels whose minimum SAD is tied: StereoBM's candidate index runs from DMax down
          // and keeps the first minimum, the largest d, as the stage does; counted to show
          // that the rule was exercised.
          int best = 0, at_min = 0;
          std::vector<int> sad(kNumDisp);
          for (int k = 0; k < kNumDisp; ++k) {
            sad[k] = sad_reference(pl.data(), pr.data(), l.width, u, v, c.dmin + k, c.n);
            if (sad[k] <= sad[best]) best = k;
          }
          for (int k = 0; k < kNumDisp; ++k) at_min += sad[k] == sad[best];
          ties += at_min > 1;
        }
      INFO("N " << c.n << ", dmin " << c.dmin << ", cap " << c.cap << ", setUseOptimized("
                << optimized << "): " << same << " of " << region << " equal, " << ties
                << " with a tied minimum, " << outside_diff << " outside the valid region");
      CHECK(same == region);
      CHECK(ties > 0);
      CHECK(outside_diff == 0);
    }
}

}  // namespace
