// SPDX-License-Identifier: Apache-2.0
// [hls] The ground-removal model against the plain-loop reference: a road with objects standing
// on it (ground removed, objects kept, the causal skirt where predicted), random maps and
// configurations, Tsukuba's truth and a disparity-stage map, enable = 0, the frame function,
// the default configuration from b / h, latency, and broken frames.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <vector>

#include "hls/ground/ground.hpp"
#include "host/disparity/run_model.hpp"
#include "host/ground/run_model.hpp"
#include "host/io/tsukuba.hpp"
#include "host/reference/ground_ref.hpp"
#include "sim/core/stream_check.hpp"
#include "sim/models/ground_model.hpp"
#include "tests/ground/ground_maps.hpp"

namespace {

using namespace scw::test::ground;
using scw::ground::default_ground_config;
using scw::ground::remove_ground;
using scw::reference::ground_reference;

using Params = scw::hls::ground::GroundParams<64>;
using Model = scw::sim::GroundModel<Params>;

/// `maps` back to back through a fresh model (no stalls); returns its output beats and checks
/// that nothing was flagged.
std::vector<GroundBeat> run_model(const std::vector<cv::Mat>& maps, const GroundConfig& cfg,
                                  const scw::sim::StallPattern& p = {}) {
  auto m = std::make_unique<Model>(cfg);
  const auto beats = map_beats(maps);
  const auto r = scw::sim::run_stream(*m, beats, p, beats.size());
  REQUIRE_FALSE(r.timed_out);
  CHECK(r.violations.empty());
  CHECK_FALSE(m->kernel().error());
  return r.out;
}

int count_zero(const cv::Mat& m) { return static_cast<int>(m.total()) - cv::countNonZero(m); }

bool kept(const cv::Mat& in, const cv::Mat& out, int x, int y) {
  return in.at<std::int16_t>(y, x) == out.at<std::int16_t>(y, x);
}

}  // namespace

TEST_CASE("default_ground_config follows b / h", "[hls][ground]") {
  // The project's rig (host/warning/setup.hpp): b = 0.54 m, camera 1.20 m above the road:
  // 0.45 px per row, 4.5 px over the window, 72 in Q11.4.
  const auto c = default_ground_config(0.54, 1.20);
  CHECK(c.enable);
  CHECK(c.step_tol_q4 == 4);
  CHECK(c.min_rise_q4 == 36);
  CHECK(c.max_rise_q4 == 144);
  CHECK(c == GroundConfig{});  // the struct's defaults are that rig's
  // b = 0.24 m at h = 0.80 m: 0.3 px per row, 3 px over the window, 48 -> 24 .. 96.
  const auto xb3 = default_ground_config(0.24, 0.80);
  CHECK(xb3.min_rise_q4 == 24);
  CHECK(xb3.max_rise_q4 == 96);
  // Rounded to nearest; a flat face (rise 0) is never ground, however small b / h.
  const auto odd = default_ground_config(0.12, 1.5);  // 12.8 -> 6.4 .. 25.6
  CHECK(odd.min_rise_q4 == 6);
  CHECK(odd.max_rise_q4 == 26);
  CHECK(default_ground_config(0.001, 10.0).min_rise_q4 == 1);
  CHECK_THROWS_AS(default_ground_config(0.0, 1.2), std::invalid_argument);
  CHECK_THROWS_AS(default_ground_config(0.5, -1.0), std::invalid_argument);
  CHECK_THROWS_AS(default_ground_config(std::numeric_limits<double>::quiet_NaN(), 1.2),
                  std::invalid_argument);
  CHECK_THROWS_AS(default_ground_config(200.0, 1.0), std::invalid_argument);  // > 32767
}

TEST_CASE("configurations outside the ports are refused", "[hls][ground]") {
  GroundConfig c;
  c.step_tol_q4 = -1;
  CHECK_THROWS_AS(scw::hls::ground::Ground<Params>(c), std::invalid_argument);
  c = GroundConfig{};
  c.max_rise_q4 = 32768;
  CHECK_THROWS_AS(Model(c), std::invalid_argument);
  const cv::Mat d = road_scene(16, 16, Road{}, {});
  CHECK_THROWS_AS(remove_ground(d, c), std::invalid_argument);
  CHECK_THROWS_AS(remove_ground(cv::Mat(4, 4, CV_8UC1), GroundConfig{}), std::invalid_argument);
  CHECK_THROWS_AS(remove_ground(cv::Mat(2, 2049, CV_16SC1), GroundConfig{}), std::invalid_argument);
}

TEST_CASE("a road with objects: ground removed, objects kept, the causal skirt", "[hls][ground]") {
  const Road road{8, 0.45};  // the default rig's b / h
  // Two tall objects (A reaching the top of the frame, B above the horizon) and a low one, C,
  // seen against the road: 7 rows tall, below the horizon.
  const Box a{5, 14, 0, 40}, b{30, 37, 2, 55}, c{48, 55, 30, 36};
  const cv::Mat scene = road_scene(64, 64, road, {a, b, c});
  // The defaults, and min_rise raised near the expected 72: the skirt grows toward 10 rows.
  for (const int min_rise : {36, 70}) {
    GroundConfig cfg = default_ground_config(0.54, 1.20);
    cfg.min_rise_q4 = min_rise;
    DYNAMIC_SECTION("min_rise " << min_rise) {
      const cv::Mat out = remove_ground(scene, cfg);
      REQUIRE(differences(out, ground_reference(scene, cfg)) == 0);
      CHECK(run_model({scene}, cfg) == map_beats({out}));  // remove_ground is the model

      // Open road: removed once the window holds 11 road rows (below horizon + 10), else kept.
      for (const int x : {0, 20, 28, 42, 63})
        for (int y = 0; y < 64; ++y) {
          INFO("road x " << x << " y " << y);
          if (y > road.horizon + 10)
            CHECK(out.at<std::int16_t>(y, x) == 0);
          else
            CHECK(kept(scene, out, x, y));
        }
      // Tall objects: every pixel kept (their windows are flat, or reach above the frame or
      // into the sky).
      for (const Box& o : {a, b})
        for (int y = o.top; y <= o.foot; ++y)
          for (int x = o.x0; x <= o.x1; ++x) CHECK(kept(scene, out, x, y));
      // The causal skirt: road n = 1 .. 10 rows below a foot still has object rows at the top
      // of its window, rise = road(foot + n) - road(foot); kept while that is below min_rise
      // (about min_rise / (16 b / h) rows, at most 10), removed after.
      for (const Box& o : {a, b}) {
        int skirt = 0;
        for (int n = 1; o.foot + n < 64; ++n) {
          const int y = o.foot + n;
          const bool predicted_kept = n <= 10 && road.q4(y) - road.q4(o.foot) < min_rise;
          skirt += predicted_kept ? 1 : 0;
          for (int x = o.x0; x <= o.x1; ++x) {
            INFO("below foot " << o.foot << ": n " << n << " x " << x);
            CHECK(kept(scene, out, x, y) == predicted_kept);
            if (!predicted_kept) CHECK(out.at<std::int16_t>(y, x) == 0);
          }
        }
        INFO("skirt of " << skirt << " rows");
        const int expect = static_cast<int>(std::ceil(min_rise / (16 * road.px_per_row))) - 1;
        CHECK(std::abs(skirt - expect) <= 1);
        CHECK(skirt <= 10);
      }
      // The low object C, road visible above it: its rows whose window reaches the road above
      // (y - 10 < top) with a rise road(foot) - road(y - 10) within the limits go (the
      // documented limit for objects under ~20 rows tall); the others stay.
      int c_removed = 0;
      for (int y = c.top; y <= c.foot; ++y) {
        const int rise = road.q4(c.foot) - road.q4(y - 10);
        const bool predicted_removed = y - 10 < c.top && y - 10 > road.horizon &&
                                       rise >= cfg.min_rise_q4 && rise <= cfg.max_rise_q4;
        for (int x = c.x0; x <= c.x1; ++x) {
          INFO("object C x " << x << " y " << y);
          CHECK(kept(scene, out, x, y) == !predicted_removed);
        }
        c_removed += predicted_removed ? 1 : 0;
      }
      if (min_rise == 36) CHECK(c_removed > 0);
    }
  }
}

TEST_CASE("model equals the reference on random maps and configurations", "[hls][ground]") {
  // Frames of several sizes back to back through one model: full width, narrower (rows set by
  // eol), rows of one and two pixels, frames shorter than the window.
  const int sizes[][2] = {{64, 48}, {40, 30}, {17, 12}, {1, 15}, {2, 13}, {64, 11}, {5, 3}};
  long removed = 0, kept_valid = 0;
  for (std::uint64_t seed = 1; seed <= 24; ++seed) {
    const GroundConfig cfg = seed <= 4 ? GroundConfig{} : random_config(seed);
    std::vector<cv::Mat> maps;
    std::uint64_t s = seed * 100;
    for (const auto& wh : sizes) maps.push_back(noisy_scene(wh[0], wh[1], s++));
    maps.push_back(uniform_map(64, 20, s++));
    INFO("seed " << seed << ": enable " << cfg.enable << " tol " << cfg.step_tol_q4 << " rise "
                 << cfg.min_rise_q4 << " .. " << cfg.max_rise_q4);
    const auto out = run_model(maps, cfg);
    REQUIRE(out == expected_beats(maps, cfg));
    for (const auto& m : maps) {
      const cv::Mat r = ground_reference(m, cfg);
      removed += count_zero(r) - count_zero(m);
      for (int y = 0; y < m.rows; ++y)
        for (int x = 0; x < m.cols; ++x)
          kept_valid += scw::hls::ground::is_valid(r.at<std::uint16_t>(y, x)) ? 1 : 0;
    }
  }
  // Both outcomes occur often: the maps exercise the rule, not only its validity checks.
  CHECK(removed > 5000);
  CHECK(kept_valid > 5000);
}

TEST_CASE("enable = 0 passes every map unchanged", "[hls][ground]") {
  GroundConfig off;
  off.enable = false;
  std::vector<cv::Mat> maps{road_scene(64, 40, Road{4, 0.6}, {{3, 9, 10, 30}}),
                            noisy_scene(50, 30, 7), uniform_map(64, 16, 8)};
  CHECK(run_model(maps, off) == map_beats(maps));
  for (const auto& m : maps) CHECK(differences(remove_ground(m, off), m) == 0);
}

TEST_CASE("the frame function (the HLS top) equals the cycle model", "[hls][ground]") {
  const std::vector<cv::Mat> maps{road_scene(64, 40, Road{4, 0.45}, {{3, 9, 10, 30}}),
                                  noisy_scene(33, 25, 3)};
  const auto in = map_beats(maps);
  std::vector<GroundBeat> out(in.size());
  auto g = std::make_unique<scw::hls::ground::Ground<Params>>(GroundConfig{});
  scw::hls::ground::ground_frame(*g, in.data(), out.data(), static_cast<int>(in.size()));
  CHECK(out == run_model(maps, GroundConfig{}));
  CHECK(out == expected_beats(maps, GroundConfig{}));
  CHECK_FALSE(g->error());
}

TEST_CASE("latency is the named constant, one beat per clock", "[hls][ground]") {
  STATIC_REQUIRE(Params::kLatency == 5);
  STATIC_REQUIRE(Params::kLineLatency == scw::hls::LineBufferParams<1, 64, 11>::kLatency + 1);
  const std::vector<cv::Mat> maps{noisy_scene(64, 20, 5)};
  const auto beats = map_beats(maps);
  Model m{GroundConfig{}};
  const auto r = scw::sim::run_stream(m, beats, {}, beats.size());
  CHECK(r.cycles == static_cast<std::int64_t>(beats.size()) + Params::kLatency);
  std::int64_t cycles = 0;
  remove_ground(maps[0], GroundConfig{}, &cycles);
  CHECK(cycles == static_cast<std::int64_t>(beats.size()) + Params::kLatency);
}

TEST_CASE("model equals the reference on Tsukuba", "[hls][ground]") {
  const cv::Mat gt16 = scw::host::io::read_tsukuba_truth(SCW_DATA_DIR "/tsukuba", CV_16SC1);
  const auto [l, r] = scw::host::io::read_tsukuba_pair(SCW_DATA_DIR "/tsukuba");
  const cv::Mat thesis = scw::disparity::disparity_image(
      l, r, 9, 0, 15, scw::disparity::mode_config(scw::disparity::Mode::thesis, l.cols, l.rows, 0));
  const cv::Mat opencv = scw::disparity::disparity_image(
      l, r, 9, 0, 15, scw::disparity::mode_config(scw::disparity::Mode::opencv, l.cols, l.rows, 0));
  REQUIRE(thesis.type() == CV_16SC1);
  GroundConfig permissive;  // a floor-like slope over the window, to make the rule fire
  permissive.step_tol_q4 = 16;
  permissive.min_rise_q4 = 16;
  permissive.max_rise_q4 = 320;
  GroundConfig off;
  off.enable = false;
  struct Named {
    const char* name;
    cv::Mat map;
  };
  const std::vector<Named> maps{{"ground truth", gt16},
                                {"thesis-mode map", thesis},
                                {"opencv-mode map (negative invalid code)", opencv}};
  for (const auto& [name, map] : maps) {
    for (const auto& cfg : {GroundConfig{}, permissive, off}) {
      INFO(name << ", rise " << cfg.min_rise_q4 << " .. " << cfg.max_rise_q4 << ", enable "
                << cfg.enable);
      const cv::Mat out = remove_ground(map, cfg);
      CHECK(out.type() == map.type());
      CHECK(differences(out, ground_reference(map, cfg)) == 0);
      if (!cfg.enable) CHECK(differences(out, map) == 0);
      if (cfg == permissive) CHECK(count_zero(out) > count_zero(map));
    }
  }
  // CV_16U in (the labelling stage's input type): the same bits out.
  cv::Mat thesis_u;
  thesis.convertTo(thesis_u, CV_16U);
  CHECK(differences(remove_ground(thesis_u, permissive), remove_ground(thesis, permissive)) == 0);
}

TEST_CASE("broken frames are flagged and the next frame is correct", "[hls][ground]") {
  using Small = scw::hls::ground::GroundParams<32>;
  const GroundConfig cfg{};
  const cv::Mat good = road_scene(32, 24, Road{2, 0.45}, {{4, 9, 0, 15}});
  const auto good_beats = map_beats({good});
  const auto good_ref = expected_beats({good}, cfg);
  std::vector<GroundBeat> bad;
  SECTION("a row longer than MaxWidthPx") { bad = map_beats({noisy_scene(35, 14, 9)}); }
  SECTION("a frame cut short mid-row (sof before eol)") {
    bad = map_beats({noisy_scene(32, 14, 10)});
    bad.resize(bad.size() - 5);
  }
  auto in = bad;
  in.insert(in.end(), good_beats.begin(), good_beats.end());
  scw::sim::GroundModel<Small> m(cfg);
  const auto r = scw::sim::run_stream(m, in, {}, in.size());
  REQUIRE(r.out.size() == in.size());  // one beat out per beat in, whatever the geometry
  CHECK(m.kernel().error());
  const std::vector<GroundBeat> tail(r.out.end() - static_cast<long>(good_ref.size()), r.out.end());
  CHECK(tail == good_ref);
}
