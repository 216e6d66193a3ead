// SPDX-License-Identifier: Apache-2.0
// [hls] The road stage's kernel against the floating-point reference (the road found and
// followed from a wrong start, the pixels on it removed, objects kept, an implausible fit
// refused), the fit's integer arithmetic against doubles, the cycle model against the frame
// function under stalls, and the configuration checks.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "hls/road/road.hpp"
#include "host/reference/road_ref.hpp"
#include "host/road/run_model.hpp"
#include "host/road/setup.hpp"
#include "host/vectors/road_maps.hpp"
#include "sim/core/stream_check.hpp"
#include "sim/models/road_model.hpp"

namespace {

using namespace scw::fixtures;
using scw::hls::road::Line;
using scw::hls::road::RoadConfig;
using scw::reference::RoadLinePx;

constexpr double kUnit = scw::hls::road::kPxUnit;
using scw::reference::to_px;
RoadLinePx px(const Line& l) { return to_px(l); }

/// Pixels where the kernel and the reference disagree, leaving out those within 1/64 px of
/// either band's edge (where the kernel's rounding of its lines may decide the other way).
int disagreements(const cv::Mat& q4, const cv::Mat& kernel, const cv::Mat& ref,
                  const RoadLinePx& road, const RoadConfig& cfg) {
  int bad = 0;
  for (int v = 0; v < q4.rows; ++v)
    for (int u = 0; u < q4.cols; ++u) {
      if (kernel.at<std::uint16_t>(v, u) == ref.at<std::uint16_t>(v, u)) continue;
      const double dr = road.a * v + road.b, d = q4.at<std::uint16_t>(v, u) / 16.0;
      const double t = cfg.tol_q4 / 16.0 + cfg.tol_rel_q8 / 256.0 * dr;
      if (std::abs(std::abs(d - dr) - t) > 1.0 / 64 && std::abs(dr - 1.0) > 1.0 / 64) ++bad;
    }
  return bad;
}

}  // namespace

TEST_CASE("road: found from a wrong start and followed, its pixels removed, objects kept",
          "[hls][road]") {
  RoadScene scene;
  scene.width = 96;
  scene.height = 64;
  const auto cfg = road_config(scene, GENERATE(0.8, 1.0, 1.3), GENERATE(-3.0, 0.0, 4.0));
  scw::road::RoadFilter kernel(cfg);
  RoadLinePx road = px(cfg.nominal);
  int fitted = 0;
  for (std::uint32_t f = 0; f < 5; ++f) {
    const cv::Mat q4 = road_map(scene, 100 + f);
    const cv::Mat out = kernel.filter(q4);
    // The two roads agree to 1/100 px over the frame.
    const RoadLinePx used = px(kernel.road());
    CHECK(std::abs(used.a - road.a) * scene.height < 0.01);
    CHECK(std::abs(used.b - road.b) < 0.01);
    const auto ref = scw::reference::road_reference(q4, road, cfg);
    CHECK(disagreements(q4, out, ref.kept, road, cfg) == 0);
    fitted += ref.fitted;
    road = ref.next;
  }
  CHECK(fitted == 5);
  // After a frame the road is the planted one, and the last frame lost its road but not its
  // objects: every pixel left is far from the road.
  CHECK(road.a == Approx(scene.slope).epsilon(0.02));
  CHECK(-road.b / road.a == Approx(scene.horizon).margin(0.5));
  const cv::Mat q4 = road_map(scene, 200);
  const cv::Mat out = kernel.filter(q4);
  int road_px = 0, left_on_road = 0, object_px = 0, objects_kept = 0;
  for (int v = 0; v < q4.rows; ++v)
    for (int u = 0; u < q4.cols; ++u) {
      const int c = q4.at<std::uint16_t>(v, u);
      if (c == 0) continue;
      const double dr = scene.slope * (v - scene.horizon);
      const bool on_road = std::abs(c / 16.0 - dr) <= 0.3;
      (on_road ? road_px : object_px) += 1;
      if (on_road && dr >= 1.2 && out.at<std::uint16_t>(v, u) != 0) ++left_on_road;
      if (!on_road && std::abs(c / 16.0 - dr) > 1.0 + 0.16 * dr)
        objects_kept += out.at<std::uint16_t>(v, u) != 0;
    }
  CHECK(road_px > 2000);
  CHECK(left_on_road == 0);
  CHECK(object_px > 0);
  CHECK(objects_kept > 0);
}

TEST_CASE("road: an implausible fit keeps the road it had", "[hls][road]") {
  RoadScene scene;
  // A slope three times the nominal's plausible range, and a horizon 20 rows off.
  RoadScene wrong = scene;
  SECTION("slope") { wrong.slope = scene.slope * 3; }
  SECTION("horizon") { wrong.horizon = scene.horizon + 20; }
  const auto cfg = road_config(scene, 1.0, 0.0);
  scw::road::RoadFilter kernel(cfg);
  for (std::uint32_t f = 0; f < 3; ++f) {
    const cv::Mat q4 = road_map(wrong, f);
    kernel.filter(q4);
    CHECK(kernel.road() == cfg.nominal);
    const auto ref = scw::reference::road_reference(q4, px(cfg.nominal), cfg);
    CHECK_FALSE(ref.fitted);
  }
  // Too few pixels: the same.
  auto few = road_config(scene, 1.0, 0.0, 1u << 19);
  scw::road::RoadFilter k2(few);
  k2.filter(road_map(scene, 1));
  k2.filter(road_map(scene, 2));
  CHECK(k2.road() == few.nominal);
}

TEST_CASE("road: the fit's integer arithmetic against doubles", "[hls][road]") {
  // Points on lines with random slopes and horizons: the fixed-point line is the exact one
  // rounded down to 2^-12 code.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> slope(0.2, 1.5), hor(10, 300);
  RoadConfig cfg;
  cfg.a_min = 1;
  cfg.a_max = static_cast<std::int32_t>(scw::hls::road::kMaxSlope);
  cfg.h_min = 0;
  cfg.h_max = 1023;
  cfg.min_count = 1;
  for (int t = 0; t < 200; ++t) {
    const double a = slope(rng), h = hor(rng);
    scw::hls::road::FitSums s;
    for (int v = static_cast<int>(h) + 2; v < 1000; v += 3)
      for (int k = 0; k < 4; ++k) {
        const auto d = static_cast<std::uint64_t>(std::lround(a * (v - h) * 16));
        if (d == 0 || d > 0x7fff) continue;
        s.n += 1, s.sv += v, s.svv += std::uint64_t(v) * v, s.sd += d, s.svd += v * d;
      }
    const Line l = scw::hls::road::fit_line(s, cfg, Line{});
    const double n = s.n, den = n * s.svv - double(s.sv) * s.sv;
    const double fa = (n * s.svd - double(s.sv) * s.sd) / den;  // codes a row
    CHECK(std::abs(l.a - fa * 4096) <= 1.0);
    const double fb = (s.sd - (l.a / 4096.0) * s.sv) / n;
    CHECK(std::abs(l.b - fb * 4096) <= 1.0);
  }
}

TEST_CASE("road: the cycle model equals the frame function under stalls, the fit holds sof",
          "[hls][road]") {
  using Params = scw::hls::road::RoadParams<2, 64, 32>;
  using Beat = Params::in_beat;
  RoadScene scene;
  scene.height = 32;
  scene.horizon = 8;
  const auto cfg = road_config(scene, 1.2, 2.0, 20);
  std::vector<Beat> beats;
  for (std::uint32_t f = 0; f < 3; ++f) {
    const cv::Mat m = road_map(scene, f);
    for (int v = 0; v < m.rows; ++v)
      for (int u = 0; u < m.cols; u += 2) {
        Beat b;
        b.px = {m.at<std::uint16_t>(v, u), m.at<std::uint16_t>(v, u + 1)};
        b.sof = v == 0 && u == 0;
        b.eol = u + 2 == m.cols;
        beats.push_back(b);
      }
  }
  scw::hls::road::Road<Params> ref(cfg);
  std::vector<Beat> want(beats.size());
  scw::hls::road::road_frame(ref, beats.data(), want.data(), static_cast<int>(beats.size()));
  CHECK(ref.line() != cfg.nominal);  // the road moved
  int zeroed = 0;
  for (std::size_t i = 0; i < beats.size(); ++i) zeroed += want[i].px != beats[i].px;
  CHECK(zeroed > 100);
  for (const auto& p : scw::sim::StallPattern::all(3)) {
    scw::sim::RoadModel<Params> m(cfg);
    const auto r = scw::sim::run_stream(m, beats, p, beats.size());
    REQUIRE_FALSE(r.timed_out);
    CHECK(r.out == want);
  }
  // No stalls: 3 fits of kFitClocks + 1 clocks each on top of a beat a clock.
  scw::sim::RoadModel<Params> m(cfg);
  const auto r = scw::sim::run_stream(m, beats, {}, beats.size());
  CHECK(r.cycles == static_cast<std::int64_t>(beats.size()) +
                        3 * (scw::hls::road::kFitClocks + 1) + scw::hls::road::kLatency);
}

TEST_CASE("road: configuration values out of range are named", "[hls][road]") {
  RoadConfig c;
  c.a_max = 1 << 18;
  CHECK_THROWS_WITH(scw::hls::road::check_config(c), Catch::Contains("a_max"));
  c = RoadConfig{};
  c.a_min = 5;
  c.a_max = 4;
  CHECK_THROWS_WITH(scw::hls::road::check_config(c), Catch::Contains("a_min = 5 above"));
  c = RoadConfig{};
  c.min_count = 0;
  CHECK_THROWS_WITH(scw::hls::road::check_config(c), Catch::Contains("min_count"));
  scw::road::RoadSetup s = scw::road::rig_setup(0.54, 700, 240, 1.2);
  s.camera_height_m = -1;
  CHECK_THROWS_WITH(scw::road::to_fixed(s), Catch::Contains("camera height"));
  s = scw::road::rig_setup(0.54, 700, 240, 1.2);
  s.tol_rel = 1.5;
  CHECK_THROWS_WITH(scw::road::to_fixed(s), Catch::Contains("relative tolerance"));
  // The rig's defaults: 0.45 px a row from row 240.
  const auto f = scw::road::to_fixed(scw::road::rig_setup(0.54, 700, 240, 1.2));
  CHECK(f.nominal.a == std::lround(0.45 * kUnit));
  CHECK(-f.nominal.b / double(f.nominal.a) == Approx(240).margin(0.01));
  // A camera pitched 1 degree down: the horizon f tan(1 deg) = 12.2 rows above the principal
  // point, the slope b cos(1 deg) / H; the plausible range stays about the level camera's.
  const auto p = scw::road::to_fixed(scw::road::rig_setup(0.54, 700, 240, 1.2, 1.0));
  CHECK(-p.nominal.b / double(p.nominal.a) == Approx(240 - 700 * std::tan(0.01745329)).margin(0.01));
  CHECK(p.nominal.a == std::lround(0.45 * std::cos(0.01745329) * kUnit));
  CHECK(p.a_min == f.a_min);
  CHECK(p.h_max == f.h_max);
  CHECK_THROWS_WITH(scw::road::to_fixed(scw::road::rig_setup(0.54, 700, 240, 1.2, -3.5)),
                    Catch::Contains("camera pitch -3.5"));
  scw::road::RoadFilter k(f);
  CHECK_THROWS_WITH(k.filter(cv::Mat(4, 4, CV_8UC1)), Catch::Contains("16-bit"));
}
