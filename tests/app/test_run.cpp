// SPDX-License-Identifier: Apache-2.0
// [app] The whole chain on synthetic rectified pairs whose geometry is known: a textured box
// standing in the tunnel ahead of a far textured wall decides the frame, at the distance its
// disparity gives; moving it towards the car raises the severity and the tracker keeps it.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "host/app/run.hpp"
#include "host/warning/setup.hpp"

namespace {

using scw::hls::warning::Severity;

constexpr int kW = 320, kH = 240;
constexpr double kF = 300.0, kB = 0.5;  // px, m: d = 150 / z

/// Left and right images of a wall at `z_wall` and a box (lateral centre x, width w, height h,
/// standing on the road 1.2 m below the camera) at `z_box`, both covered in random texture
/// fixed to the scene, so block matching finds d = f b / z on each.
std::pair<cv::Mat, cv::Mat> render(double z_wall, double x, double z_box, double w, double h) {
  std::mt19937 rng(7);
  cv::Mat wall(kH, 2 * kW, CV_8UC1), box(kH, 2 * kW, CV_8UC1);
  cv::randu(wall, 0, 255);
  cv::randu(box, 0, 255);
  const double cu = (kW - 1) / 2.0, cv_ = (kH - 1) / 2.0;
  const double d_wall = kF * kB / z_wall, d_box = kF * kB / z_box;
  const int u0 = static_cast<int>(std::lround(cu + kF * (x - w / 2) / z_box));
  const int u1 = static_cast<int>(std::lround(cu + kF * (x + w / 2) / z_box));
  const int v0 = static_cast<int>(std::lround(cv_ - kF * (-1.2 + h) / z_box));
  const int v1 = static_cast<int>(std::lround(cv_ - kF * (-1.2) / z_box));
  cv::Mat left(kH, kW, CV_8UC1), right(kH, kW, CV_8UC1);
  for (int v = 0; v < kH; ++v)
    for (int u = 0; u < kW; ++u) {
      const bool in_box = v >= v0 && v <= v1 && u >= u0 && u <= u1;
      left.at<std::uint8_t>(v, u) = in_box ? box.at<std::uint8_t>(v, u) : wall.at<std::uint8_t>(v, u);
      // The right camera sees the left's column u at u - d: the box covers u0 - d .. u1 - d.
      const int ub = static_cast<int>(std::lround(u + d_box));
      const bool box_r = v >= v0 && v <= v1 && ub >= u0 && ub <= u1;
      const int uw = static_cast<int>(std::lround(u + d_wall));
      right.at<std::uint8_t>(v, u) = box_r ? box.at<std::uint8_t>(v, ub)
                                           : wall.at<std::uint8_t>(v, std::min(uw, 2 * kW - 1));
    }
  return {left, right};
}

scw::app::RunOptions options() {
  scw::app::RunOptions o;
  o.window = 9;
  o.min_disp = 0;
  o.max_disp = 63;
  o.min_area = 100;
  o.warning.focal_px = kF;
  o.warning.baseline_m = kB;
  o.warning.cu_px = (kW - 1) / 2.0;
  o.warning.cv_px = (kH - 1) / 2.0;
  return o;
}

}  // namespace

TEST_CASE("run: a box in the tunnel decides at the distance its disparity gives", "[app]") {
  scw::app::Runner runner(options(), std::nullopt);
  const double z_box = 6.0;  // d = 25 px
  const auto [l, r] = render(40.0, -0.3, z_box, 1.0, 1.8);
  const auto out = runner.process(l, r);
  const auto& res = out.result;
  REQUIRE(out.deciding_label > 0);
  CHECK(res.in_tunnel);
  CHECK(res.severity == Severity::kHigh);  // in the tunnel, 4.35 m from the bumper
  CHECK(std::abs(res.d_max / 16.0 - 25.0) <= 1.0);
  const double expected = std::hypot(std::hypot(0.0, 0.0), z_box) - 1.65;
  CHECK(std::abs(res.distance_mm / 1000.0 - expected) < 0.5);  // block matching: within 1 px
  const auto j = scw::app::frame_json(0, out);
  for (const char* key : {"frame", "severity", "distance_m", "closest_uv", "disparity", "bbox",
                          "objects", "flags"})
    CHECK(j.contains(key));
  CHECK(j["severity"] == "high");
}

TEST_CASE("run: the same box beside the tunnel is medium when near it, low when far", "[app]") {
  scw::app::Runner near_runner(options(), std::nullopt);
  const auto [l1, r1] = render(40.0, 2.2, 6.0, 0.8, 1.8);  // box edge 0.15 m beyond the tunnel
  CHECK(near_runner.process(l1, r1).result.severity == Severity::kMedium);
  scw::app::Runner far_runner(options(), std::nullopt);
  const auto [l2, r2] = render(40.0, 4.5, 8.0, 0.8, 1.8);  // 2.4 m beyond it
  CHECK(far_runner.process(l2, r2).result.severity == Severity::kLow);
}

TEST_CASE("run: a flat marking on the road is no obstacle, the minimum height and the road stage "
          "say so", "[app]") {
  auto o = options();
  scw::app::Runner runner(o, std::nullopt);
  const auto [l, r] = render(40.0, -0.3, 6.0, 1.5, 0.2);  // 20 cm high: a painted sign, seen flat
  const auto out = runner.process(l, r);
  // Only the far wall is an obstacle: low, decided at the wall's disparity (3.75 px).
  CHECK(out.result.severity == Severity::kLow);
  CHECK(std::abs(out.result.d_max / 16.0 - 3.75) <= 1.0);
  // Without the minimum height the road stage still removes it (it lies within its band)...
  o.warning.min_height_m = 0.0;
  scw::app::Runner no_limit(o, std::nullopt);
  CHECK(no_limit.process(l, r).result.severity == Severity::kLow);
  // ...and without either it is the nearest obstacle, in the tunnel: high.
  o.road = false;
  scw::app::Runner neither(o, std::nullopt);
  CHECK(neither.process(l, r).result.severity == Severity::kHigh);
}

TEST_CASE("run: errors name what is wrong", "[app]") {
  scw::app::Runner runner(options(), std::nullopt);
  const cv::Mat a(kH, kW, CV_8UC1, cv::Scalar(0)), b(kH, kW + 8, CV_8UC1, cv::Scalar(0));
  CHECK_THROWS_WITH(runner.process(a, b), Catch::Contains("differ in size"));
  auto o = options();
  o.max_disp = 4096;  // beyond what the warning stage's table covers
  CHECK_THROWS_WITH(scw::app::Runner(o, std::nullopt), Catch::Contains("disparity limit"));
}
