// SPDX-License-Identifier: Apache-2.0
// scw_rectify against the C++ model beat for beat (the same cycle trace) under every stall
// pattern, both against the integer reference; malformed streams flagged and recovered from.
#include <catch2/catch.hpp>

#include "host/reference/rectify_ref.hpp"
#include "sim/models/rectify_model.hpp"
#include "sim/rtl/rectify_rtl.hpp"
#include "sim/rtl/rtl_params.hpp"
#include "tests/common/primitive_configs.hpp"
#include "tests/common/twin_check.hpp"
#include "tests/rectify/random_maps.hpp"
#include "tests/rectify/rectify_configs.hpp"
#include "Vrectify_p1.h"
#include "Vrectify_p1_scw_rectify.h"
#include "Vrectify_p2.h"
#include "Vrectify_p2_scw_rectify.h"
#include "Vrectify_p4.h"
#include "Vrectify_p4_scw_rectify.h"

namespace {

using namespace scw;
using hls::rectify::MapPoint;
using hls::rectify::RectifyConfig;

// The Verilated parameters must be the C++ ones (tests/CMakeLists.txt passes them with -G).
static_assert(sim::rectify_params_match<Vrectify_p1_scw_rectify, test::RectifyP1>());
static_assert(sim::rectify_params_match<Vrectify_p2_scw_rectify, test::RectifyP2>());
static_assert(sim::rectify_params_match<Vrectify_p4_scw_rectify, test::RectifyP4>());

template <typename Params>
std::vector<typename Params::pixel_beat> reference_beats(const test::RectifyFrame& f, int w,
                                                         int h) {
  const auto ref = reference::rectify_reference(f.raw.data(), w, h, f.map.data(), w, h,
                                                Params::kFracBits);
  return sim::frame_beats_of<typename Params::pixel_beat>(ref.data(), w, h);
}

/// Runs model and RTL on the same streams under `pattern`: both follow the handshake rules and
/// have the same cycle trace; returns the RTL's run.
template <typename VM, typename Params>
sim::RunResult<typename Params::pixel_beat> run_twins(const test::RectifyStreams<Params>& s,
                                                      const RectifyConfig& cfg,
                                                      const sim::StallPattern& pattern,
                                                      std::size_t expected_out,
                                                      std::uint8_t& err_cpp, std::uint8_t& err_rtl) {
  sim::RectifyModel<Params> cpp(cfg);
  auto rtl = sim::make_rectify_rtl<VM, Params>("rectify", cfg);
  const auto rc = sim::run_join(cpp, s.raw, s.map, pattern, expected_out);
  const auto rr = sim::run_join(rtl, s.raw, s.map, pattern, expected_out);
  test::check_twin_runs(rc, rr);
  err_cpp = cpp.kernel().error();
  err_rtl = static_cast<std::uint8_t>(rtl.dut().err_o);
  return rr;
}

/// `m` moved down by `rows` raw rows (clamped as the host does): places a warp in the window.
std::vector<MapPoint> moved(std::vector<MapPoint> m, int rows, int w, int h, int frac_bits) {
  for (auto& p : m) {
    p.y += rows * (1 << frac_bits);
    p = test::clamp_point(p, w, h, frac_bits);
  }
  return m;
}

template <typename VM, typename Params>
void check_rectify(int width, int lead) {
  constexpr int H = 12;
  const RectifyConfig cfg{width, H, lead};
  // Frames back to back: random maps, a shift, a rotation, a strong barrel.
  std::vector<test::RectifyFrame> frames;
  frames.push_back({test::random_image(width, H, 1),
                    test::random_map(width, H, Params::kFracBits, lead, Params::kRows, 2)});
  // Warps need rows v - 2 .. v + 2; moved by lead - 3 rows they sit in the window
  // v + lead - 6 .. v + lead - 1 of an 8-row stage.
  frames.push_back({test::random_image(width, H, 3),
                    test::shift_map(width, H, Params::kFracBits, -1.25, lead - 2.25)});
  frames.push_back({test::random_image(width, H, 4),
                    moved(test::rotation_map(width, H, Params::kFracBits, 5.0, width / 2.0, 6.0),
                          lead - 3, width, H, Params::kFracBits)});
  frames.push_back({test::random_image(width, H, 5),
                    test::random_map(width, H, Params::kFracBits, lead, Params::kRows, 6)});
  std::vector<typename Params::pixel_beat> expected;
  for (const auto& f : frames) {
    REQUIRE(test::map_in_window(f.map, width, H, Params::kFracBits, lead, Params::kRows));
    const auto e = reference_beats<Params>(f, width, H);
    expected.insert(expected.end(), e.begin(), e.end());
  }
  const auto s = test::rectify_streams<Params>(frames, width, H);
  for (const auto& pattern : sim::StallPattern::all(3)) {
    DYNAMIC_SECTION("stalls " << pattern.name()) {
      std::uint8_t ec = 0, er = 0;
      const auto rr = run_twins<VM, Params>(s, cfg, pattern, expected.size(), ec, er);
      CHECK(rr.out == expected);
      CHECK(ec == 0);
      CHECK(er == 0);
    }
  }
}

}  // namespace

TEST_CASE("scw_rectify equals the rectify model beat for beat", "[rectify][rtl]") {
  SECTION("P = 1, lead 3") { check_rectify<Vrectify_p1, test::RectifyP1>(32, 3); }
  SECTION("P = 1, 24 wide, lead 2") { check_rectify<Vrectify_p1, test::RectifyP1>(24, 2); }
  SECTION("P = 2, lead 1") { check_rectify<Vrectify_p2, test::RectifyP2>(32, 1); }
  SECTION("P = 2, lead 4") { check_rectify<Vrectify_p2, test::RectifyP2>(32, 4); }
  SECTION("P = 4, lead 5") { check_rectify<Vrectify_p4, test::RectifyP4>(32, 5); }
  SECTION("P = 4, 16 wide, lead 2") { check_rectify<Vrectify_p4, test::RectifyP4>(16, 2); }
}

namespace {

/// A malformed frame followed by a good one: both languages flag the same error bits and
/// agree cycle for cycle, the output stays whole W x H frames, and the good frame is exact.
template <typename VM, typename Params>
void check_recovery(const test::RectifyStreams<Params>& bad, std::uint8_t expect_err) {
  constexpr int W = 32, H = 12, D = 3;
  const test::RectifyFrame good{test::random_image(W, H, 90),
                                test::rotation_map(W, H, Params::kFracBits, -4.0, 16.0, 6.0)};
  auto s = bad;
  const auto g = test::rectify_streams<Params>({good}, W, H);
  s.raw.insert(s.raw.end(), g.raw.begin(), g.raw.end());
  s.map.insert(s.map.end(), g.map.begin(), g.map.end());
  const auto expected = reference_beats<Params>(good, W, H);
  const std::size_t frame_beats = expected.size();
  for (const auto& pattern : {sim::StallPattern{}, sim::StallPattern::parse("random:5")}) {
    DYNAMIC_SECTION("stalls " << pattern.name()) {
      std::uint8_t ec = 0, er = 0;
      const auto rr =
          run_twins<VM, Params>(s, RectifyConfig{W, H, D}, pattern, 2 * frame_beats, ec, er);
      REQUIRE(rr.out.size() == 2 * frame_beats);
      CHECK(ec == expect_err);
      CHECK(er == expect_err);
      // Whole frames: sof and eol where the geometry puts them, in the bad frame too.
      for (std::size_t i = 0; i < rr.out.size(); ++i) {
        CHECK(rr.out[i].sof == (i % frame_beats == 0));
        CHECK(rr.out[i].eol == ((i + 1) % (W / Params::kPpc) == 0));
      }
      const std::vector<typename Params::pixel_beat> tail(rr.out.begin() + frame_beats,
                                                          rr.out.end());
      CHECK(tail == expected);
    }
  }
}

}  // namespace

TEST_CASE("scw_rectify flags malformed streams and recovers on the next frame",
          "[rectify][rtl][malformed]") {
  using Params = test::RectifyP2;
  constexpr int W = 32, H = 12;
  const test::RectifyFrame f{test::random_image(W, H, 80), test::shift_map(W, H, 5, 0.5, 0.5)};
  auto s = test::rectify_streams<Params>({f}, W, H);
  using hls::rectify::kErrMapGeometry;
  using hls::rectify::kErrMapWindow;
  using hls::rectify::kErrRawGeometry;
  SECTION("raw frame cut short (the next sof arrives mid-frame)") {
    s.raw.resize(s.raw.size() - 40);
    check_recovery<Vrectify_p2>(s, kErrRawGeometry);
  }
  SECTION("raw row too short (an early eol)") {
    s.raw[20].eol = true;
    s.raw.erase(s.raw.begin() + 21);
    check_recovery<Vrectify_p2>(s, kErrRawGeometry);
  }
  SECTION("stray raw beats before the sof") {
    s.raw.insert(s.raw.begin(), s.raw.begin() + 5, s.raw.begin() + 8);
    check_recovery<Vrectify_p2>(s, kErrRawGeometry);
  }
  SECTION("map frame cut short") {
    s.map.resize(s.map.size() - 70);
    check_recovery<Vrectify_p2>(s, kErrMapGeometry);
  }
  SECTION("map row too long (a missing eol)") {
    s.map[15].eol = false;
    s.map.insert(s.map.begin() + 16, s.map[15]);
    check_recovery<Vrectify_p2>(s, kErrMapGeometry);
  }
  SECTION("map needing raw rows outside the window") {
    // Output row 8 samples raw row 0: 8 rows back, the stage (8 rows, lead 3) reaches 3.
    s.map[8 * W / 2 + 3].px[0] = MapPoint{5 << 5, 0};
    check_recovery<Vrectify_p2>(s, kErrMapWindow);
  }
}
