// SPDX-License-Identifier: Apache-2.0
// [rtl] scw_beat_split against sim::BeatSplitModel clock for clock under every stall pattern,
// both against a plain serialisation; one output beat per clock on a continuous input.
#include <catch2/catch.hpp>
#include <cstdint>
#include <random>
#include <vector>

#include "Vbeat_split_p1.h"
#include "Vbeat_split_p1_scw_beat_split.h"
#include "Vbeat_split_p2.h"
#include "Vbeat_split_p2_scw_beat_split.h"
#include "Vbeat_split_p4.h"
#include "Vbeat_split_p4_scw_beat_split.h"
#include "sim/beat_split_model.hpp"
#include "sim/beat_split_rtl.hpp"
#include "sim/rtl_params.hpp"
#include "sim/stream_check.hpp"
#include "tests/common/twin_check.hpp"
#include "tests/pipeline/split_check_configs.hpp"

namespace {

using scw::sim::StallPattern;
using scw::test::pipeline::split_pixel_t;

// split_check.cmake builds these three with -G.
static_assert(scw::sim::beat_split_params_match<Vbeat_split_p1_scw_beat_split, split_pixel_t, 1>());
static_assert(scw::sim::beat_split_params_match<Vbeat_split_p2_scw_beat_split, split_pixel_t, 2>());
static_assert(scw::sim::beat_split_params_match<Vbeat_split_p4_scw_beat_split, split_pixel_t, 4>());

template <int P>
using VSplit = scw::sim::ByPpc<P, Vbeat_split_p1, Vbeat_split_p2, Vbeat_split_p4>;
template <int P>
using InBeat = scw::hls::Beat<split_pixel_t, P>;
using OutBeat = scw::hls::Beat<split_pixel_t, 1>;

/// Random pixels with random flags: the block must not interpret them (a sof on a beat that is
/// not the frame's first, an eol anywhere), plus whole frames so the usual shape is covered.
template <int P>
std::vector<InBeat<P>> test_beats(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<InBeat<P>> v;
  for (int f = 0; f < 2; ++f)  // two 3-row frames, 4 beats per row
    for (int y = 0; y < 3; ++y)
      for (int x = 0; x < 4; ++x) {
        InBeat<P> b;
        for (auto& p : b.px) p = static_cast<split_pixel_t>(rng());
        b.sof = x == 0 && y == 0;
        b.eol = x == 3;
        v.push_back(b);
      }
  for (std::size_t i = 0; i < n; ++i) {
    InBeat<P> b;
    for (auto& p : b.px) p = static_cast<split_pixel_t>(rng());
    b.sof = rng() % 5 == 0;
    b.eol = rng() % 3 == 0;
    v.push_back(b);
  }
  return v;
}

/// The plain serialisation: every pixel in order, sof on each beat's first, eol on its last.
template <int P>
std::vector<OutBeat> serialise(const std::vector<InBeat<P>>& in) {
  std::vector<OutBeat> out;
  for (const auto& b : in)
    for (int i = 0; i < P; ++i) {
      OutBeat o;
      o.px[0] = b.px[static_cast<std::size_t>(i)];
      o.sof = b.sof && i == 0;
      o.eol = b.eol && i == P - 1;
      out.push_back(o);
    }
  return out;
}

template <int P>
void check_split() {
  const auto in = test_beats<P>(150, 100 + P);
  const auto expected = serialise<P>(in);
  for (const auto& pattern : StallPattern::all(3)) {
    DYNAMIC_SECTION("stalls " << pattern.name()) {
      scw::sim::BeatSplitModel<split_pixel_t, P> cpp;
      scw::sim::BeatSplitRtl<VSplit<P>, split_pixel_t, P> rtl("beat_split");
      const auto rc = scw::sim::run_stream(cpp, in, pattern, expected.size());
      const auto rr = scw::sim::run_stream(rtl, in, pattern, expected.size());
      scw::test::check_twin_runs(rc, rr);
      CHECK(rc.out == expected);
    }
  }
}

template <int P>
void check_throughput() {
  const auto in = test_beats<P>(40, 200 + P);
  const std::int64_t n = static_cast<std::int64_t>(in.size()) * P;
  scw::sim::BeatSplitModel<split_pixel_t, P> cpp;
  scw::sim::BeatSplitRtl<VSplit<P>, split_pixel_t, P> rtl("beat_split");
  const auto rc = scw::sim::run_stream(cpp, in, StallPattern{}, static_cast<std::size_t>(n));
  const auto rr = scw::sim::run_stream(rtl, in, StallPattern{}, static_cast<std::size_t>(n));
  scw::test::check_twin_runs(rc, rr);
  // The first beat is taken in cycle 0 and presented from cycle 1; from then on one pixel
  // leaves every clock, so the last of N * P leaves in cycle N * P.
  CHECK(rr.cycles == n + 1);
  CHECK(rr.out == serialise<P>(in));
  std::int64_t out_cycles = 0, in_cycles = 0;
  for (const auto& c : rr.trace) {
    out_cycles += c.out_valid && c.out_ready;
    in_cycles += c.in_valid && c.in_ready;
  }
  CHECK(out_cycles == n);
  CHECK(in_cycles == static_cast<std::int64_t>(in.size()));
  // Once the first pixel is out, out_valid never drops until the input runs dry.
  for (std::int64_t c = 1; c <= n; ++c) {
    INFO("cycle " << c);
    CHECK(rr.trace[static_cast<std::size_t>(c)].out_valid);
  }
}

}  // namespace

TEST_CASE("scw_beat_split equals the model clock for clock and serialises every pixel",
          "[pipeline][rtl][beat_split]") {
  SECTION("P = 1 (a stream register)") { check_split<1>(); }
  SECTION("P = 2") { check_split<2>(); }
  SECTION("P = 4") { check_split<4>(); }
}

TEST_CASE("scw_beat_split gives one output beat per clock on a continuous input",
          "[pipeline][rtl][beat_split][throughput]") {
  SECTION("P = 1") { check_throughput<1>(); }
  SECTION("P = 2") { check_throughput<2>(); }
  SECTION("P = 4") { check_throughput<4>(); }
}
