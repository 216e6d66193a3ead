// SPDX-License-Identifier: Apache-2.0
// [rtl] scw_ground against the ground-removal model clock for clock (the same cycle trace) under
// every stall pattern, both against the plain-loop reference; broken frames flagged alike with
// the next frame correct.
#include <catch2/catch.hpp>
#include <cstdint>
#include <vector>

#include "host/disparity/run_model.hpp"
#include "host/io/tsukuba.hpp"
#include "sim/models/ground_model.hpp"
#include "sim/models/pipeline_shell.hpp"
#include "sim/rtl/ground_rtl.hpp"
#include "sim/rtl/rtl_stream.hpp"
#include "tests/common/twin_check.hpp"
#include "tests/ground/ground_maps.hpp"
#include "Vground_lb.h"
#include "Vground_lb_scw_line_buffer.h"
#include "Vground_w20.h"
#include "Vground_w20_scw_ground.h"
#include "Vground_w32.h"
#include "Vground_w32_scw_ground.h"

namespace {

using namespace scw::test::ground;
using scw::hls::ground::GroundParams;
using scw::sim::StallPattern;

// tests/ground/rtl.cmake builds the same two with -G.
using Params32 = GroundParams<32>;
using Params20 = GroundParams<20>;  // not a power of two: the RAM is not full depth
static_assert(scw::sim::ground_params_match<Vground_w32_scw_ground, Params32>());
static_assert(scw::sim::ground_params_match<Vground_w20_scw_ground, Params20>());
// tests/ground/rtl.cmake: scw_line_buffer as scw_ground<32> instantiates it (two 8-bit lanes a
// disparity, RdReg), its latency the stage's kLineLatency.
static_assert(Vground_lb_scw_line_buffer::Ppc == 2 && Vground_lb_scw_line_buffer::MaxWidthPx == 64 &&
              Vground_lb_scw_line_buffer::Rows == Params32::kRows &&
              Vground_lb_scw_line_buffer::Latency == Params32::kLineLatency);

/// One run of each twin on the same beats.
struct TwinRun {
  std::vector<GroundBeat> out;  // the RTL's
  std::int64_t cycles = 0;
  bool err_cpp = false, err_rtl = false;
};

/// The model and the RTL on `beats` under `pattern` until every beat has left: the same cycle
/// trace and outputs (check_twin_runs).
template <typename VM, typename Params>
TwinRun run_twins(const std::vector<GroundBeat>& beats, const GroundConfig& cfg,
                  const StallPattern& pattern) {
  scw::sim::GroundModel<Params> cpp(cfg);
  auto rtl = scw::sim::make_ground_rtl<VM, Params>("ground", cfg);
  const auto rc = scw::sim::run_stream(cpp, beats, pattern, beats.size());
  const auto rr = scw::sim::run_stream(rtl, beats, pattern, beats.size());
  scw::test::check_twin_runs(rc, rr);
  return {rr.out, rr.cycles, cpp.kernel().error(), rtl.dut().err_o != 0};
}

/// `maps` back to back under every stall pattern: twins equal, output equals the reference.
template <typename VM, typename Params>
void check_maps(const std::vector<cv::Mat>& maps, const GroundConfig& cfg) {
  const auto beats = map_beats(maps);
  const auto expected = expected_beats(maps, cfg);
  for (const auto& pattern : StallPattern::all(3)) {
    INFO("stalls " << pattern.name());
    const auto r = run_twins<VM, Params>(beats, cfg, pattern);
    CHECK(r.out == expected);
    CHECK_FALSE(r.err_cpp);
    CHECK_FALSE(r.err_rtl);
  }
}

GroundConfig with_min_rise(int min_rise) {
  GroundConfig c;
  c.min_rise_q4 = min_rise;
  return c;
}

GroundConfig disabled() {
  GroundConfig c;
  c.enable = false;
  return c;
}

}  // namespace

TEST_CASE("scw_ground equals the model clock for clock on a road with objects", "[ground][rtl]") {
  // A tall object reaching the top, one standing above the horizon, a low one seen against the
  // road (docs/ground.md: its lower rows go).
  const cv::Mat scene =
      road_scene(32, 40, Road{3, 0.45}, {{2, 7, 0, 22}, {12, 17, 1, 30}, {22, 28, 20, 26}});
  const cv::Mat steep = road_scene(32, 40, Road{0, 1.2}, {{5, 20, 10, 25}});
  for (const auto& cfg : {GroundConfig{}, with_min_rise(70), disabled(), random_config(41),
                          random_config(42), random_config(43)}) {
    DYNAMIC_SECTION("enable " << cfg.enable << " tol " << cfg.step_tol_q4 << " rise "
                              << cfg.min_rise_q4 << " .. " << cfg.max_rise_q4) {
      check_maps<Vground_w32, Params32>({scene, steep}, cfg);
    }
  }
}

TEST_CASE("scw_ground equals the model clock for clock on random maps of several sizes",
          "[ground][rtl]") {
  // Full width, narrower rows (set by eol), rows of one beat (each beat reads the RAM word the
  // one before is writing: the line buffer forwards it), 1 x 1 frames (a sof after a sof), and
  // frames shorter than the window.
  const int sizes[][2] = {{32, 24}, {20, 16}, {1, 12}, {2, 12}, {1, 1}, {1, 1}, {32, 11}, {7, 3}};
  for (std::uint64_t seed : {1, 2, 3, 4}) {
    std::vector<cv::Mat> maps;
    std::uint64_t s = seed * 100;
    for (const auto& wh : sizes) maps.push_back(noisy_scene(wh[0], wh[1], s++));
    maps.push_back(uniform_map(32, 12, s++));
    const GroundConfig cfg = seed == 1 ? GroundConfig{} : random_config(seed + 50);
    DYNAMIC_SECTION("seed " << seed) { check_maps<Vground_w32, Params32>(maps, cfg); }
  }
  SECTION("a build 20 wide") {
    check_maps<Vground_w20, Params20>(
        {noisy_scene(20, 30, 7), noisy_scene(13, 14, 8), uniform_map(20, 12, 9)}, GroundConfig{});
  }
}

TEST_CASE("the stage's line buffer, RAM output registered, equals hls::LineBuffer beat for beat",
          "[ground][rtl]") {
  // Rows of one and two beats: a beat reads the column the previous beat, or the one before
  // it, has not written back yet (the two forwarded words); then full and odd widths.
  using Kernel = scw::hls::LineBuffer<std::uint16_t, Params32::line_params>;
  using Shell = scw::sim::PipelineShell<Kernel, Params32::kLineLatency>;
  using Rtl = scw::sim::RtlStream<Vground_lb, Kernel::in_type, Kernel::out_type>;
  const int sizes[][2] = {{32, 14}, {1, 12}, {2, 13}, {3, 12}, {1, 1}, {2, 2}, {17, 13}, {32, 12}};
  std::vector<cv::Mat> maps;
  std::uint64_t s = 40;
  for (const auto& wh : sizes) maps.push_back(noisy_scene(wh[0], wh[1], s++));
  const auto beats = map_beats(maps);
  for (const auto& pattern : StallPattern::all(3)) {
    INFO("stalls " << pattern.name());
    Shell cpp;
    Rtl rtl("line_buffer");
    const auto rc = scw::sim::run_stream(cpp, beats, pattern, beats.size());
    const auto rr = scw::sim::run_stream(rtl, beats, pattern, beats.size());
    scw::test::check_twin_runs(rc, rr);
    CHECK(rr.out.size() == beats.size());
  }
}

TEST_CASE("scw_ground equals the model clock for clock on Tsukuba crops", "[ground][rtl]") {
  const cv::Mat gt16 = scw::host::io::read_tsukuba_truth(SCW_DATA_DIR "/tsukuba", CV_16SC1);
  const auto [l, r] = scw::host::io::read_tsukuba_pair(SCW_DATA_DIR "/tsukuba");
  const cv::Mat d = scw::disparity::disparity_image(
      l, r, 9, 0, 15, scw::disparity::mode_config(scw::disparity::Mode::thesis, l.cols, l.rows, 0));
  // The table and the lamp's base (rows 200 .. 247) and the statue's head (rows 60 .. 107).
  const cv::Rect low(150, 200, 32, 48), high(140, 60, 32, 48);
  const std::vector<cv::Mat> maps{gt16(low).clone(), d(low).clone(), gt16(high).clone(),
                                  d(high).clone()};
  GroundConfig permissive;
  permissive.step_tol_q4 = 16;
  permissive.min_rise_q4 = 16;
  permissive.max_rise_q4 = 320;
  for (const auto& cfg : {GroundConfig{}, permissive}) {
    DYNAMIC_SECTION("rise " << cfg.min_rise_q4 << " .. " << cfg.max_rise_q4) {
      check_maps<Vground_w32, Params32>(maps, cfg);
    }
  }
}

TEST_CASE("scw_ground takes a beat per clock and presents it Latency clocks later",
          "[ground][rtl]") {
  const std::vector<cv::Mat> maps{noisy_scene(32, 16, 5)};
  const auto beats = map_beats(maps);
  const auto r = run_twins<Vground_w32, Params32>(beats, GroundConfig{}, StallPattern{});
  CHECK(r.cycles == static_cast<std::int64_t>(beats.size()) + Params32::kLatency);
  CHECK(r.out == expected_beats(maps, GroundConfig{}));
}

TEST_CASE("scw_ground flags broken frames like the model, the next frame correct",
          "[ground][rtl]") {
  const GroundConfig cfg{};
  const cv::Mat good = road_scene(20, 24, Road{2, 0.45}, {{4, 9, 0, 15}});
  const auto good_beats = map_beats({good});
  const auto good_ref = expected_beats({good}, cfg);
  std::vector<GroundBeat> bad;
  SECTION("a row longer than MaxWidthPx") { bad = map_beats({noisy_scene(23, 14, 9)}); }
  SECTION("a frame cut short mid-row (sof before eol)") {
    bad = map_beats({noisy_scene(20, 14, 10)});
    bad.resize(bad.size() - 5);
  }
  SECTION("a misplaced eol, then a sof mid-row") {
    bad = map_beats({noisy_scene(20, 14, 11)});
    bad[45].eol = true;  // row 2 ends early: later rows are read one column off
    bad.resize(bad.size() - 3);
  }
  auto in = bad;
  in.insert(in.end(), good_beats.begin(), good_beats.end());
  for (const auto& pattern : StallPattern::all(3)) {
    INFO("stalls " << pattern.name());
    const auto r = run_twins<Vground_w20, Params20>(in, cfg, pattern);
    REQUIRE(r.out.size() == in.size());  // one beat out per beat in, whatever the geometry
    CHECK(r.err_cpp);
    CHECK(r.err_rtl);
    const std::vector<GroundBeat> tail(r.out.end() - static_cast<long>(good_ref.size()),
                                       r.out.end());
    CHECK(tail == good_ref);
  }
}
