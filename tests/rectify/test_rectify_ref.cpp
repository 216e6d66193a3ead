// SPDX-License-Identifier: Apache-2.0
// The integer rectify reference against the thesis's worked example, cv::remap and edge cases.
#include <catch2/catch.hpp>

#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/core/utility.hpp>
#include <opencv2/imgproc.hpp>

#include "host/reference/rectify_ref.hpp"
#include "tests/common/primitive_configs.hpp"
#include "tests/rectify/random_maps.hpp"

namespace {

using scw::hls::rectify::MapPoint;
using scw::reference::bilinear_reference;
using scw::reference::rectify_reference;

constexpr int kF = 5;  // OpenCV's INTER_BITS: the only F cv::remap's fixed-point maps take
constexpr int kS = 1 << kF;

/// cv::remap with OpenCV's own fixed-point map pair built straight from the MapPoints (integer
/// part x >> 5, y >> 5; fraction index (y & 31) * 32 + (x & 31)), INTER_LINEAR, border 0.
std::vector<std::uint8_t> cv_remap(const std::vector<std::uint8_t>& raw, int width, int height,
                                   const std::vector<MapPoint>& map, int out_width,
                                   int out_height) {
  cv::Mat xy(out_height, out_width, CV_16SC2), frac(out_height, out_width, CV_16UC1);
  for (int v = 0; v < out_height; ++v)
    for (int u = 0; u < out_width; ++u) {
      const MapPoint& p = map[static_cast<std::size_t>(v) * out_width + u];
      xy.at<cv::Vec2s>(v, u) = cv::Vec2s(static_cast<short>(p.x >> kF),
                                         static_cast<short>(p.y >> kF));
      frac.at<std::uint16_t>(v, u) =
          static_cast<std::uint16_t>((p.y & (kS - 1)) * kS + (p.x & (kS - 1)));
    }
  const cv::Mat src(height, width, CV_8UC1, const_cast<std::uint8_t*>(raw.data()));
  cv::Mat dst;
  cv::remap(src, dst, xy, frac, cv::INTER_LINEAR, cv::BORDER_CONSTANT, cv::Scalar(0));
  REQUIRE(dst.isContinuous());
  return std::vector<std::uint8_t>(dst.data, dst.data + dst.total());
}

struct Agreement {
  std::size_t pixels = 0, exact = 0;
  int max_diff = 0;
  void add(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b) {
    REQUIRE(a.size() == b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
      const int d = std::abs(int{a[i]} - int{b[i]});
      exact += d == 0;
      max_diff = std::max(max_diff, d);
    }
    pixels += a.size();
  }
  void merge(const Agreement& o) {
    pixels += o.pixels;
    exact += o.exact;
    max_diff = std::max(max_diff, o.max_diff);
  }
  double share() const { return pixels ? static_cast<double>(exact) / pixels : 1.0; }
};

/// Compares the reference with cv::remap on one image and map; returns the counts.
Agreement compare_with_opencv(const std::vector<std::uint8_t>& raw, int width, int height,
                              const std::vector<MapPoint>& map, const std::string& what) {
  const auto ref = rectify_reference(raw.data(), width, height, map.data(), width, height, kF);
  const auto cv = cv_remap(raw, width, height, map, width, height);
  Agreement a;
  a.add(ref, cv);
  INFO(what << ": " << a.exact << " of " << a.pixels << " exact, max difference " << a.max_diff);
  CHECK(a.max_diff <= 1);
  // Stronger than the spec's 1 grey level, and measured with OpenCV 4.6: for F = 5 OpenCV's
  // 15-bit weights are exactly 32 times ours ((S - fx)(S - fy) / 1024 is exact in float), so
  // its (sum + 2^14) >> 15 is our (sum + 2^9) >> 10 (docs/rectify.md). A failure here with a
  // different OpenCV means its arithmetic changed, not necessarily that ours is wrong.
  CHECK(a.exact == a.pixels);
  return a;
}

void report(const Agreement& a, const std::string& what, const char* other = "cv::remap") {
  std::cout << "[rectify:ref] " << what << ": " << a.exact << " of " << a.pixels
            << " pixels equal " << other << " (" << 100.0 * a.share() << " %), max difference "
            << a.max_diff << "\n";
}

/// An image with smooth gradients and edges (closer to a camera picture than noise).
std::vector<std::uint8_t> pattern_image(int width, int height) {
  std::vector<std::uint8_t> img(static_cast<std::size_t>(width) * height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      img[static_cast<std::size_t>(y) * width + x] = static_cast<std::uint8_t>(
          ((x / 16 + y / 16) % 2 ? 200 : 40) + (x * 13 + y * 7) % 50);
  return img;
}

}  // namespace

TEST_CASE("Fig. 5.14: the thesis's worked example comes out as 123", "[rectify][ref]") {
  // Pixels 99 146 (row 153, columns 104 and 105) and 121 133 (row 154), sampled at
  // (104.4876, 153.1628), quantised with cvRound(x * 32).
  const int x = cvRound(104.4876 * kS), y = cvRound(153.1628 * kS);
  REQUIRE(x == 3344);  // 104 + 16/32
  REQUIRE(y == 4901);  // 153 + 5/32
  CHECK(bilinear_reference(99, 146, 121, 133, x & (kS - 1), y & (kS - 1), kF) == 123);

  const int w = 110, h = 160;
  std::vector<std::uint8_t> img(static_cast<std::size_t>(w) * h, 7);
  img[153 * w + 104] = 99;
  img[153 * w + 105] = 146;
  img[154 * w + 104] = 121;
  img[154 * w + 105] = 133;
  const MapPoint p{x, y};
  const auto out = rectify_reference(img.data(), w, h, &p, 1, 1, kF);
  CHECK(out.at(0) == 123);
  // Output size need not match the raw size: a 1 x 1 "image" sampling that point.
  CHECK(cv_remap(img, w, h, {p}, 1, 1).at(0) == 123);
}

TEST_CASE("bilinear_reference: integer positions copy the pixel, weights sum to S*S",
          "[rectify][ref]") {
  for (int f = 1; f <= 8; ++f) {
    const int s = 1 << f;
    CHECK(bilinear_reference(17, 200, 3, 255, 0, 0, f) == 17);
    for (int c : {0, 1, 127, 254, 255})
      for (int fx = 0; fx < s; fx += std::max(1, s / 7))
        for (int fy = 0; fy < s; fy += std::max(1, s / 5))
          REQUIRE(bilinear_reference(c, c, c, c, fx, fy, f) == c);
    // Halfway between 0 and 1 rounds up: (S*S/2 + S*S/2) >> 2F = 1.
    CHECK(bilinear_reference(0, 1, 0, 1, s / 2, 0, f) == 1);
    CHECK(bilinear_reference(0, 255, 0, 255, s - 1, s - 1, f) ==
          (255 * (s - 1) * s + s * s / 2) / (s * s));
  }
}

TEST_CASE("rectify_reference equals cv::remap exactly (spec bound: 1 grey level)",
          "[rectify][ref]") {
  Agreement total;
  SECTION("random maps") {
    const int sizes[][4] = {{16, 8, 1, 4}, {33, 17, 3, 8}, {64, 48, 5, 16}, {128, 96, 30, 32},
                            {160, 120, 7, 8}};
    std::uint64_t seed = 1;
    for (const auto& sz : sizes)
      for (int rep = 0; rep < 6; ++rep, ++seed) {
        const int w = sz[0], h = sz[1];
        const auto img = scw::test::random_image(w, h, seed);
        const auto map = scw::test::random_map(w, h, kF, sz[2], sz[3], seed * 77);
        total.merge(
            compare_with_opencv(img, w, h, map, "random map seed " + std::to_string(seed)));
      }
    report(total, "random maps, random images");
  }
  SECTION("shift, rotation and barrel maps") {
    struct Case {
      int w, h;
    };
    for (const Case c : {Case{40, 30}, Case{97, 61}, Case{320, 240}, Case{640, 480}}) {
      const auto img = scw::test::random_image(c.w, c.h, static_cast<std::uint64_t>(c.w));
      const auto pic = pattern_image(c.w, c.h);
      const std::vector<std::pair<std::string, std::vector<MapPoint>>> maps = {
          {"shift", scw::test::shift_map(c.w, c.h, kF, 3.37, -2.81)},
          {"rotation", scw::test::rotation_map(c.w, c.h, kF, 4.0, c.w * 0.4, c.h * 0.55)},
          {"barrel", scw::test::barrel_map(c.w, c.h, kF, -0.3)},
          {"pincushion", scw::test::barrel_map(c.w, c.h, kF, 0.25)},
      };
      for (const auto& [name, map] : maps) {
        const std::string what = name + " " + std::to_string(c.w) + "x" + std::to_string(c.h);
        const auto a = compare_with_opencv(img, c.w, c.h, map, what + " noise");
        const auto b = compare_with_opencv(pic, c.w, c.h, map, what + " pattern");
        if (c.w == 640) {
          report(a, what + ", random image");
          report(b, what + ", pattern image");
        }
        total.merge(a);
        total.merge(b);
      }
    }
    report(total, "shift/rotation/barrel maps, all sizes");
  }
  CHECK(total.max_diff <= 1);
}

TEST_CASE("cv::remap gives the same result with and without its optimised code paths",
          "[rectify][ref]") {
  const int w = 640, h = 480;
  const auto img = scw::test::random_image(w, h, 5);
  const auto map = scw::test::barrel_map(w, h, kF, -0.3);
  const auto rnd = scw::test::random_map(w, h, kF, 20, 64, 9);
  const bool was = cv::useOptimized();
  cv::setUseOptimized(true);
  const auto fast = cv_remap(img, w, h, map, w, h);
  const auto fast_rnd = cv_remap(img, w, h, rnd, w, h);
  cv::setUseOptimized(false);
  const auto slow = cv_remap(img, w, h, map, w, h);
  const auto slow_rnd = cv_remap(img, w, h, rnd, w, h);
  cv::setUseOptimized(was);
  Agreement a;
  a.add(fast, slow);
  a.add(fast_rnd, slow_rnd);
  report(a, "cv::remap with setUseOptimized(true)", "cv::remap with setUseOptimized(false)");
  CHECK(a.exact == a.pixels);
  Agreement r;
  r.add(rectify_reference(img.data(), w, h, map.data(), w, h, kF), slow);
  r.add(rectify_reference(img.data(), w, h, rnd.data(), w, h, kF), slow_rnd);
  report(r, "reference", "cv::remap with setUseOptimized(false)");
  CHECK(r.max_diff <= 1);
  CHECK(r.exact == r.pixels);
}

TEST_CASE("rectify_reference edge cases: outside, border, constant image", "[rectify][ref]") {
  const int w = 23, h = 11;
  const auto img = scw::test::random_image(w, h, 42);
  const auto px = [&](int x, int y) { return int{img[static_cast<std::size_t>(y) * w + x]}; };
  const auto ref1 = [&](MapPoint p) {
    return int{rectify_reference(img.data(), w, h, &p, 1, 1, kF)[0]};
  };

  SECTION("points fully outside give 0") {
    std::vector<MapPoint> pts;
    for (int t = -3 * kS; t <= (h + 3) * kS; t += 7) {
      pts.push_back({-kS, t});
      pts.push_back({-5 * kS - 3, t});
      pts.push_back({w * kS, t});
      pts.push_back({w * kS + 9, t});
      pts.push_back({(w + 40) * kS, t});
    }
    for (int t = -3 * kS; t <= (w + 3) * kS; t += 5) {
      pts.push_back({t, -kS});
      pts.push_back({t, -2 * kS - 1});
      pts.push_back({t, h * kS});
      pts.push_back({t, h * kS + kS - 1});
    }
    const auto out = rectify_reference(img.data(), w, h, pts.data(), static_cast<int>(pts.size()),
                                       1, kF);
    for (std::size_t i = 0; i < pts.size(); ++i) {
      INFO("x = " << pts[i].x << ", y = " << pts[i].y);
      REQUIRE(out[i] == 0);
    }
    CHECK(cv_remap(img, w, h, pts, static_cast<int>(pts.size()), 1) == out);
  }

  SECTION("points on the border blend with zeros") {
    std::vector<MapPoint> pts;
    for (int f = 0; f < kS; ++f)
      for (int g : {0, 1, kS / 2, kS - 1}) {
        const int y0 = 4;
        // Last column: column W is outside.
        MapPoint p{(w - 1) * kS + f, y0 * kS + g};
        CHECK(ref1(p) == bilinear_reference(px(w - 1, y0), 0, px(w - 1, y0 + 1), 0, f, g, kF));
        pts.push_back(p);
        // Before the first column: column -1 is outside, column 0 carries weight f.
        p = {-kS + f, y0 * kS + g};
        CHECK(ref1(p) == bilinear_reference(0, px(0, y0), 0, px(0, y0 + 1), f, g, kF));
        pts.push_back(p);
        // Last row, and above the first row.
        p = {6 * kS + g, (h - 1) * kS + f};
        CHECK(ref1(p) == bilinear_reference(px(6, h - 1), px(7, h - 1), 0, 0, g, f, kF));
        pts.push_back(p);
        p = {6 * kS + g, -kS + f};
        CHECK(ref1(p) == bilinear_reference(0, 0, px(6, 0), px(7, 0), g, f, kF));
        pts.push_back(p);
        // Corners: only one tap inside.
        p = {(w - 1) * kS + f, (h - 1) * kS + g};
        CHECK(ref1(p) == bilinear_reference(px(w - 1, h - 1), 0, 0, 0, f, g, kF));
        pts.push_back(p);
        p = {-kS + f, -kS + g};
        CHECK(ref1(p) == bilinear_reference(0, 0, 0, px(0, 0), f, g, kF));
        pts.push_back(p);
      }
    const auto out = rectify_reference(img.data(), w, h, pts.data(), static_cast<int>(pts.size()),
                                       1, kF);
    const auto cv = cv_remap(img, w, h, pts, static_cast<int>(pts.size()), 1);
    Agreement a;
    a.add(out, cv);
    report(a, "border points");
    CHECK(a.max_diff <= 1);
    CHECK(a.exact == a.pixels);
  }

  SECTION("a constant image stays constant wherever every weighted tap is inside") {
    for (int c : {0, 1, 128, 254, 255}) {
      const std::vector<std::uint8_t> flat(static_cast<std::size_t>(w) * h,
                                           static_cast<std::uint8_t>(c));
      const auto map = scw::test::random_map(w, h, kF, 3, 8, static_cast<std::uint64_t>(c) + 3);
      const auto out = rectify_reference(flat.data(), w, h, map.data(), w, h, kF);
      int inside = 0;
      for (std::size_t i = 0; i < map.size(); ++i) {
        const int x0 = map[i].x >> kF, y0 = map[i].y >> kF;
        const int fx = map[i].x & (kS - 1), fy = map[i].y & (kS - 1);
        const bool in = x0 >= 0 && y0 >= 0 && x0 + (fx ? 1 : 0) < w && y0 + (fy ? 1 : 0) < h;
        if (!in) continue;
        ++inside;
        INFO("c = " << c << ", x = " << map[i].x << ", y = " << map[i].y);
        REQUIRE(int{out[i]} == c);
      }
      CHECK(inside > static_cast<int>(map.size()) / 2);
    }
  }
}

TEST_CASE("random_map stays in the row window and covers the special points", "[rectify][ref]") {
  struct Cfg {
    int w, h, f, lead, rows;
  };
  for (const Cfg c : {Cfg{16, 8, 5, 1, 4}, Cfg{40, 30, 5, 3, 4}, Cfg{64, 64, 3, 7, 8},
                      Cfg{96, 40, 8, 10, 16}, Cfg{200, 100, 5, 31, 32}, Cfg{50, 20, 1, 2, 4}}) {
    const int s = 1 << c.f;
    int left = 0, right = 0, above = 0, below = 0, integer = 0, frac_max = 0, part = 0;
    for (std::uint64_t seed = 0; seed < 12; ++seed) {
      const auto m = scw::test::random_map(c.w, c.h, c.f, c.lead, c.rows, seed);
      REQUIRE(m.size() == static_cast<std::size_t>(c.w) * c.h);
      REQUIRE(scw::test::map_in_window(m, c.w, c.h, c.f, c.lead, c.rows));
      for (const auto& p : m) {
        REQUIRE(p.x >= -s);
        REQUIRE(p.x <= c.w * s);
        REQUIRE(p.y >= -s);
        REQUIRE(p.y <= c.h * s);
        left += p.x == -s;
        right += p.x == c.w * s;
        above += p.y == -s;
        below += p.y == c.h * s;
        part += (p.x > -s && p.x < 0) || (p.x > (c.w - 1) * s && p.x < c.w * s);
        integer += (p.x & (s - 1)) == 0 && (p.y & (s - 1)) == 0;
        frac_max += (p.x & (s - 1)) == s - 1 || (p.y & (s - 1)) == s - 1;
      }
    }
    INFO(c.w << "x" << c.h << " F=" << c.f << " D=" << c.lead << " rows=" << c.rows);
    CHECK(left > 0);
    CHECK(right > 0);
    CHECK(above > 0);
    CHECK(below > 0);
    CHECK(part > 0);
    CHECK(integer > 0);
    CHECK(frac_max > 0);
  }
}

TEST_CASE("shift, rotation and barrel maps are clamped and smooth", "[rectify][ref]") {
  const int w = 64, h = 48;
  const auto sh = scw::test::shift_map(w, h, kF, 2.5, -1.25);
  CHECK(sh[0] == MapPoint{80, -kS});  // y = -1.25 clamped to -1
  CHECK(sh[5 * w + 7] == MapPoint{304, 120});  // (9.5, 3.75) * 32
  const auto rot = scw::test::rotation_map(w, h, kF, 90.0, 10.0, 10.0);
  CHECK(rot[0 * w + 10] == MapPoint{20 * kS, 10 * kS});  // (10, 0) -> (20, 10)
  const auto id = scw::test::barrel_map(w, h, kF, 0.0);
  CHECK(id == scw::test::shift_map(w, h, kF, 0.0, 0.0));
  for (const auto* m : {&sh, &rot, &id}) {
    for (const auto& p : *m) {
      REQUIRE(p.x >= -kS);
      REQUIRE(p.x <= w * kS);
      REQUIRE(p.y >= -kS);
      REQUIRE(p.y <= h * kS);
    }
  }
  // Strong barrel distortion stays smooth: neighbours move by less than 2 pixels.
  const auto b = scw::test::barrel_map(w, h, kF, -0.3);
  for (int v = 0; v < h; ++v)
    for (int u = 1; u < w; ++u) {
      REQUIRE(std::abs(b[v * w + u].x - b[v * w + u - 1].x) < 2 * kS);
      REQUIRE(std::abs(b[v * w + u].y - b[v * w + u - 1].y) < 2 * kS);
    }
}
