// SPDX-License-Identifier: Apache-2.0
// scw_disparity against the C++ model beat for beat (the same cycle trace) under every stall
// pattern, both against the direct reference; malformed streams flagged and recovered from.
#include <catch2/catch.hpp>

#include "host/reference/disparity_ref.hpp"
#include "sim/models/disparity_model.hpp"
#include "sim/rtl/disparity_rtl.hpp"
#include "sim/rtl/rtl_params.hpp"
#include "tests/common/twin_check.hpp"
#include "tests/disparity/disparity_configs.hpp"
#include "tests/disparity/disparity_frames.hpp"
#include "Vdisparity_p1.h"
#include "Vdisparity_p1_scw_disparity.h"
#include "Vdisparity_p2.h"
#include "Vdisparity_p2_scw_disparity.h"
#include "Vdisparity_p4.h"
#include "Vdisparity_p4_scw_disparity.h"

namespace {

using namespace scw;
using hls::disparity::DisparityConfig;

template <typename Params>
using Kernel = hls::disparity::Disparity<Params>;

// The Verilated parameters and latencies must be the C++ ones (tests/CMakeLists.txt passes the
// parameters with -G; the latencies are the RTL's own).
static_assert(sim::disparity_params_match<Vdisparity_p1_scw_disparity, Kernel<test::DisparityP1>>());
static_assert(sim::disparity_params_match<Vdisparity_p2_scw_disparity, Kernel<test::DisparityP2>>());
static_assert(sim::disparity_params_match<Vdisparity_p4_scw_disparity, Kernel<test::DisparityP4>>());

template <typename Params>
using Streams = test::StereoStreams<typename Params::pixel_beat>;

/// Model and RTL on the same streams under `pattern`: same cycle trace; returns the RTL's run.
template <typename VM, typename Params>
sim::RunResult<typename Params::disp_beat> run_twins(const Streams<Params>& s,
                                                     const DisparityConfig& cfg,
                                                     const sim::StallPattern& pattern,
                                                     std::size_t expected_out, bool& err_cpp,
                                                     bool& err_rtl) {
  sim::DisparityModel<Params> cpp(cfg);
  auto rtl = sim::make_disparity_rtl<VM, Params>("disparity", cfg);
  const auto rc = sim::run_join(cpp, s.left, s.right, pattern, expected_out);
  const auto rr = sim::run_join(rtl, s.left, s.right, pattern, expected_out);
  test::check_twin_runs(rc, rr);
  err_cpp = cpp.kernel().error();
  err_rtl = rtl.dut().err_o != 0;
  return rr;
}

/// The reference output beats of `frames`, back to back.
template <typename Params>
std::vector<typename Params::disp_beat> reference_beats(const std::vector<test::StereoPair>& frames,
                                                        int w, int h, const DisparityConfig& cfg) {
  std::vector<typename Params::disp_beat> out;
  for (const auto& f : frames) {
    const auto ref =
        reference::disparity_reference(f.left.data(), f.right.data(), w, h, Params::kWindow,
                                       hls::disparity::candidates<Params::kNumDisp>(cfg), cfg);
    const auto b = sim::frame_beats_of<typename Params::disp_beat>(ref.data(), w, h);
    out.insert(out.end(), b.begin(), b.end());
  }
  return out;
}

template <typename VM, typename Params>
void check_stage(const DisparityConfig& cfg, int frames_n = 3) {
  const int w = cfg.width, h = cfg.height;
  const int nd = hls::disparity::candidates<Params::kNumDisp>(cfg);
  std::vector<test::StereoPair> frames;
  for (int f = 0; f < frames_n; ++f)
    frames.push_back(test::random_pair(w, h, cfg.dmin, nd, 100 + static_cast<unsigned>(f)));
  const auto s = test::stereo_streams<typename Params::pixel_beat>(frames, w, h);
  const auto expected = reference_beats<Params>(frames, w, h, cfg);
  for (const auto& pattern : sim::StallPattern::all(3)) {
    DYNAMIC_SECTION("stalls " << pattern.name()) {
      bool ec = true, er = true;
      const auto rr = run_twins<VM, Params>(s, cfg, pattern, expected.size(), ec, er);
      CHECK(rr.out == expected);
      CHECK_FALSE(ec);
      CHECK_FALSE(er);
    }
  }
}

DisparityConfig thesis(int w, int h, int dmin) { return hls::disparity::thesis_mode(w, h, dmin); }
DisparityConfig opencv(int w, int h, int dmin) { return hls::disparity::opencv_mode(w, h, dmin); }

}  // namespace

TEST_CASE("scw_disparity equals the disparity model beat for beat (thesis mode)",
          "[disparity][rtl]") {
  using test::DisparityP1;
  using test::DisparityP2;
  using test::DisparityP4;
  SECTION("P = 1, N = 5, d 0..5") { check_stage<Vdisparity_p1, DisparityP1>(thesis(32, 12, 0)); }
  SECTION("P = 1, 12 wide, d 3..8, SAD limit, uniqueness 20") {
    auto c = thesis(12, 11, 3);
    c.sad_limit = 900;
    c.uniqueness_ratio = 20;
    check_stage<Vdisparity_p1, DisparityP1>(c);
  }
  SECTION("P = 2, N = 7, d 1..6") { check_stage<Vdisparity_p2, DisparityP2>(thesis(32, 14, 1)); }
  SECTION("P = 2, d 5..8 (4 of 6 candidates), uniqueness 10") {
    auto c = thesis(24, 16, 5);
    c.num_disp = 4;
    c.uniqueness_ratio = 10;
    check_stage<Vdisparity_p2, DisparityP2>(c);
  }
  SECTION("P = 4, N = 5, d 2..6") { check_stage<Vdisparity_p4, DisparityP4>(thesis(32, 10, 2)); }
  SECTION("P = 4, d 7..11, sub-pixel and the opencv invalid code without prefilter") {
    auto c = thesis(32, 9, 7);
    c.subpixel = true;
    c.opencv_invalid = true;
    check_stage<Vdisparity_p4, DisparityP4>(c);
  }
}

TEST_CASE("scw_disparity equals the disparity model beat for beat (opencv mode)",
          "[disparity][rtl]") {
  using test::DisparityP1;
  using test::DisparityP2;
  using test::DisparityP4;
  SECTION("P = 1, d 0..5, odd height") { check_stage<Vdisparity_p1, DisparityP1>(opencv(32, 13, 0)); }
  SECTION("P = 1, d 4..9, cap 63, texture 40, uniqueness 5") {
    check_stage<Vdisparity_p1, DisparityP1>(hls::disparity::opencv_mode(20, 12, 4, 63, 40, 5));
  }
  SECTION("P = 2, d 3..8") { check_stage<Vdisparity_p2, DisparityP2>(opencv(32, 16, 3)); }
  SECTION("P = 2, d 0..2 (3 of 6), cap 7") {
    auto c = hls::disparity::opencv_mode(16, 12, 0, 7, 10, 15);
    c.num_disp = 3;
    check_stage<Vdisparity_p2, DisparityP2>(c);
  }
  SECTION("P = 4, d 1..5, odd height") { check_stage<Vdisparity_p4, DisparityP4>(opencv(32, 11, 1)); }
}

// The left edge band: columns decided among the candidates that fit the right image, from
// edge_candidates of them on; every lane position of the band's first column is met by the
// dmin and edge values (the band starts at dmin + edge - 1 + R).
TEST_CASE("scw_disparity equals the disparity model beat for beat (left edge band)",
          "[disparity][rtl]") {
  using test::DisparityP1;
  using test::DisparityP2;
  using test::DisparityP4;
  const auto edge = [](DisparityConfig c, int k) {
    c.edge_candidates = k;
    return c;
  };
  SECTION("P = 1, d 0..5 from 1 candidate, opencv") {
    check_stage<Vdisparity_p1, DisparityP1>(edge(opencv(32, 13, 0), 1));
  }
  SECTION("P = 1, d 3..8 from 3, thesis, uniqueness 20") {
    auto c = thesis(20, 11, 3);
    c.uniqueness_ratio = 20;
    check_stage<Vdisparity_p1, DisparityP1>(edge(c, 3));
  }
  SECTION("P = 2, d 1..6 from 2, opencv") {
    check_stage<Vdisparity_p2, DisparityP2>(edge(opencv(32, 16, 1), 2));
  }
  SECTION("P = 2, d 5..8 (4 of 6) from 3, thesis, sub-pixel") {
    auto c = thesis(24, 16, 5);
    c.num_disp = 4;
    c.subpixel = true;
    check_stage<Vdisparity_p2, DisparityP2>(edge(c, 3));
  }
  SECTION("P = 4, d 2..6 from 2, opencv") {
    check_stage<Vdisparity_p4, DisparityP4>(edge(opencv(32, 10, 2), 2));
  }
  SECTION("P = 4, d 0..4 from 4, thesis") {
    check_stage<Vdisparity_p4, DisparityP4>(edge(thesis(32, 9, 0), 4));
  }
  SECTION("P = 4, edge above the candidates: the blind band of cv::StereoBM") {
    check_stage<Vdisparity_p4, DisparityP4>(edge(opencv(32, 11, 1), 9));
  }
}

namespace {

/// A malformed frame followed by a good one: both flag the error and agree cycle for cycle,
/// the output stays whole W x H frames, and the good frame is exact.
template <typename VM, typename Params>
void check_recovery(Streams<Params> s, const DisparityConfig& cfg) {
  const int w = cfg.width, h = cfg.height;
  const test::StereoPair good = test::random_pair(w, h, cfg.dmin, Params::kNumDisp, 77);
  const auto g = test::stereo_streams<typename Params::pixel_beat>({good}, w, h);
  s.left.insert(s.left.end(), g.left.begin(), g.left.end());
  s.right.insert(s.right.end(), g.right.begin(), g.right.end());
  const auto expected = reference_beats<Params>({good}, w, h, cfg);
  const std::size_t frame_beats = expected.size();
  for (const auto& pattern : {sim::StallPattern{}, sim::StallPattern::parse("random:5")}) {
    DYNAMIC_SECTION("stalls " << pattern.name()) {
      bool ec = false, er = false;
      const auto rr = run_twins<VM, Params>(s, cfg, pattern, 2 * frame_beats, ec, er);
      REQUIRE(rr.out.size() == 2 * frame_beats);
      CHECK(ec);
      CHECK(er);
      for (std::size_t i = 0; i < rr.out.size(); ++i) {
        CHECK(rr.out[i].sof == (i % frame_beats == 0));
        CHECK(rr.out[i].eol == ((i + 1) % static_cast<std::size_t>(w / Params::kPpc) == 0));
      }
      const std::vector<typename Params::disp_beat> tail(rr.out.begin() + frame_beats,
                                                         rr.out.end());
      CHECK(tail == expected);
    }
  }
}

}  // namespace

TEST_CASE("scw_disparity flags malformed streams and recovers on the next frame",
          "[disparity][rtl][malformed]") {
  using Params = test::DisparityP2;
  for (const bool cv : {false, true}) {
    const DisparityConfig cfg = cv ? opencv(32, 12, 1) : thesis(32, 12, 1);
    auto s = test::stereo_streams<Params::pixel_beat>({test::random_pair(32, 12, 1, 6, 5)}, 32, 12);
    DYNAMIC_SECTION((cv ? "opencv mode: " : "thesis mode: ")) {
      SECTION("frame cut short (the next sof arrives mid-frame)") {
        s.left.resize(s.left.size() - 40);
        s.right.resize(s.right.size() - 40);
        check_recovery<Vdisparity_p2, Params>(s, cfg);
      }
      SECTION("row too short on both sides (an early eol)") {
        for (auto* v : {&s.left, &s.right}) {
          (*v)[20].eol = true;
          v->erase(v->begin() + 21);
        }
        check_recovery<Vdisparity_p2, Params>(s, cfg);
      }
      SECTION("stray beats before the sof") {
        for (auto* v : {&s.left, &s.right}) v->insert(v->begin(), v->begin() + 5, v->begin() + 8);
        check_recovery<Vdisparity_p2, Params>(s, cfg);
      }
      SECTION("left and right out of step (eol on one side only)") {
        s.left[7].eol = true;
        check_recovery<Vdisparity_p2, Params>(s, cfg);
      }
    }
  }
}
