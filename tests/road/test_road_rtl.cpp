// SPDX-License-Identifier: Apache-2.0
// [rtl] scw_road against sim::RoadModel clock for clock (the same cycle trace) under every stall
// pattern, over frames back to back whose fits move the road; and its fit engine alone against
// fit_line() and band() on planted, random and edge-case sums.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include <opencv2/core.hpp>

#include "hls/road/road.hpp"
#include "host/vectors/road_maps.hpp"
#include "sim/core/components.hpp"
#include "sim/core/frame_beats.hpp"
#include "sim/core/side_component.hpp"
#include "sim/core/simulator.hpp"
#include "sim/models/road_model.hpp"
#include "sim/rtl/road_rtl.hpp"
#include "sim/rtl/verilated_harness.hpp"
#include "tests/common/twin_check.hpp"
#include "Vroad_fit.h"
#include "Vroad_fit_scw_road_fit.h"
#include "Vroad_p1.h"
#include "Vroad_p1_scw_road.h"
#include "Vroad_p2.h"
#include "Vroad_p2_scw_road.h"
#include "Vroad_p4.h"
#include "Vroad_p4_scw_road.h"

namespace {

using scw::fixtures::RoadScene;
using scw::hls::road::Band;
using scw::hls::road::FitSums;
using scw::hls::road::Line;
using scw::hls::road::RoadConfig;
using scw::hls::road::RoadParams;
using scw::sim::StallPattern;

// tests/road/rtl.cmake builds the same three with -G.
using Params1 = RoadParams<1, 32, 24>;
using Params2 = RoadParams<2, 32, 24>;
using Params4 = RoadParams<4, 64, 20>;
static_assert(scw::sim::road_params_match<Vroad_p1_scw_road, Params1>());
static_assert(scw::sim::road_params_match<Vroad_p2_scw_road, Params2>());
static_assert(scw::sim::road_params_match<Vroad_p4_scw_road, Params4>());
// The engine, started 5 clocks into the fit (scw_road's FitStart), is done before it ends.
static_assert(Vroad_fit_scw_road_fit::Clocks + 5 < scw::hls::road::kFitClocks);

// ---- the stage ----------------------------------------------------------------------------------

/// What the model's kernel did over a run: its road after each fit.
struct KernelTrace {
  std::vector<Line> lines;  // the road each frame was filtered with, in order
  std::size_t zeroed = 0;   // output pixels set to 0 that were not 0
};

/// The kernel alone over `beats` (road_frame's order of fit and step), to see what the run did.
template <typename Params>
KernelTrace trace_kernel(const std::vector<typename Params::in_beat>& beats,
                         const RoadConfig& cfg) {
  scw::hls::road::Road<Params> k(cfg);
  KernelTrace t;
  for (const auto& b : beats) {
    if (k.needs_fit(b)) {
      k.fit();
      t.lines.push_back(k.line());
    }
    const auto o = k.step(b);
    for (int i = 0; i < Params::kPpc; ++i) t.zeroed += o.px[i] == 0 && b.px[i] != 0;
  }
  return t;
}

/// Distinct consecutive roads over the run (1: it never moved).
int roads_used(const KernelTrace& t) {
  int n = t.lines.empty() ? 0 : 1;
  for (std::size_t i = 1; i < t.lines.size(); ++i) n += t.lines[i] != t.lines[i - 1];
  return n;
}

/// The model and the RTL on the same beats under `pattern` until every beat has left: the same
/// cycle trace and outputs (check_twin_runs). Returns the RTL's output.
template <typename VM, typename Params>
std::vector<typename Params::out_beat> run_twins(
    const std::vector<typename Params::in_beat>& beats, const RoadConfig& cfg,
    const StallPattern& pattern, std::int64_t* cycles = nullptr) {
  scw::sim::RoadModel<Params> cpp(cfg);
  auto rtl = scw::sim::make_road_rtl<VM, Params>("road", cfg);
  const auto rc = scw::sim::run_stream(cpp, beats, pattern, beats.size());
  const auto rr = scw::sim::run_stream(rtl, beats, pattern, beats.size());
  scw::test::check_twin_runs(rc, rr);
  if (cycles) *cycles = rr.cycles;
  return rr.out;
}

/// `beats` under every stall pattern: the twins equal, and the output the kernel's.
template <typename VM, typename Params>
void check_beats(const std::vector<typename Params::in_beat>& beats, const RoadConfig& cfg) {
  std::vector<typename Params::out_beat> want(beats.size());
  scw::hls::road::Road<Params> k(cfg);
  scw::hls::road::road_frame(k, beats.data(), want.data(), static_cast<int>(beats.size()));
  for (const auto& pattern : StallPattern::all(3)) {
    INFO("stalls " << pattern.name());
    CHECK(run_twins<VM, Params>(beats, cfg, pattern) == want);
  }
}

/// CV_16UC1 maps (width a multiple of P) as one stream of frames.
template <typename Params>
std::vector<typename Params::in_beat> map_beats(const std::vector<cv::Mat>& maps) {
  using Beat = typename Params::in_beat;
  std::vector<Beat> v;
  for (const cv::Mat& m : maps) {
    REQUIRE(m.type() == CV_16UC1);
    REQUIRE(m.isContinuous());
    const auto f = scw::sim::frame_beats_of<Beat>(m.ptr<std::uint16_t>(), m.cols, m.rows);
    v.insert(v.end(), f.begin(), f.end());
  }
  return v;
}

/// The 32 x 24 road of the stage tests (MaxWidthPx 32, MaxHeight 24), its horizon at row 4.
RoadScene small_scene(double slope) {
  RoadScene s;
  s.width = 32;
  s.height = 24;
  s.slope = slope;
  s.horizon = 4;
  return s;
}

std::vector<cv::Mat> road_maps(const RoadScene& s, std::uint32_t seed, int frames) {
  std::vector<cv::Mat> maps;
  for (int f = 0; f < frames; ++f) maps.push_back(scw::fixtures::road_map(s, seed + f));
  return maps;
}

/// A map of any size: a road of random slope and horizon with noise, random codes, both invalid
/// encodings and boxes of constant disparity, in random proportions.
cv::Mat random_map(int w, int h, std::mt19937_64& rng) {
  auto uni = [&rng](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  const double slope = std::uniform_real_distribution<double>(0.2, 2.0)(rng);
  const int horizon = uni(-3, std::max(0, h / 2)), noise = uni(0, 12);
  const int p_random = uni(0, 30), p_hole = uni(0, 15);
  cv::Mat m(h, w, CV_16UC1);
  for (int v = 0; v < h; ++v)
    for (int u = 0; u < w; ++u) {
      int d = static_cast<int>(std::lround(16 * slope * (v - horizon))) + uni(-noise, noise);
      const int r = uni(0, 99);
      if (r < p_random) d = uni(0, 0xffff);
      else if (r < p_random + p_hole) d = uni(0, 1) ? 0 : 0x8000 | uni(0, 0x7fff);
      m.at<std::uint16_t>(v, u) = static_cast<std::uint16_t>(std::clamp(d, -32768, 65535));
    }
  for (int n = uni(0, 3); n > 0; --n) {
    const int u0 = uni(0, w - 1), v0 = uni(0, h - 1);
    const auto d = static_cast<std::uint16_t>(uni(1, 0x7fff));
    for (int v = v0; v < std::min(h, v0 + uni(1, h)); ++v)
      for (int u = u0; u < std::min(w, u0 + uni(1, w)); ++u) m.at<std::uint16_t>(v, u) = d;
  }
  return m;
}

/// A configuration near a road of `slope` px a row from row `horizon`, or anywhere.
RoadConfig random_config(std::mt19937_64& rng) {
  auto uni = [&rng](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  RoadScene s;
  s.slope = std::uniform_real_distribution<double>(0.2, 2.0)(rng);
  s.horizon = uni(0, 8);
  RoadConfig c = scw::fixtures::road_config(
      s, std::uniform_real_distribution<double>(0.7, 1.4)(rng), uni(-3, 3), uni(1, 60));
  c.enable = uni(0, 5) != 0;
  c.tol_q4 = static_cast<std::uint16_t>(uni(0, 64));
  c.tol_rel_q8 = static_cast<std::uint8_t>(uni(0, 255));
  c.gate_q4 = static_cast<std::uint16_t>(uni(0, 256));
  c.gate_rel_q8 = static_cast<std::uint8_t>(uni(0, 255));
  if (uni(0, 3) == 0) {  // a wide plausible range
    c.a_min = 0;
    c.a_max = static_cast<std::int32_t>(scw::hls::road::kMaxSlope);
    c.h_min = 0;
    c.h_max = 1023;
  }
  return c;
}

// ---- the fit engine alone -----------------------------------------------------------------------

struct FitOut {
  Line line;
  Band road, gate;
  int clocks = 0;  // from the start clock to the first with done_o
};

/// scw_road_fit driven from a harness: inputs set, a start pulse, clocks until done_o.
class FitRtl {
 public:
  FitRtl() : h_("road_fit") { h_.reset(); }

  FitOut run(const FitSums& s, const RoadConfig& c, const Line& keep) {
    Vroad_fit& m = h_.dut();
    m.n_i = static_cast<std::uint32_t>(s.n);
    m.sv_i = static_cast<std::uint32_t>(s.sv);
    m.svv_i = s.svv;
    m.sd_i = s.sd;
    m.svd_i = s.svd;
    m.min_count_i = c.min_count;
    m.a_min_i = static_cast<std::uint32_t>(c.a_min);
    m.a_max_i = static_cast<std::uint32_t>(c.a_max);
    m.h_min_i = c.h_min;
    m.h_max_i = c.h_max;
    m.tol_i = c.tol_q4;
    m.tol_rel_i = c.tol_rel_q8;
    m.gate_i = c.gate_q4;
    m.gate_rel_i = c.gate_rel_q8;
    m.keep_a_i = static_cast<std::uint32_t>(keep.a);
    m.keep_b_i = static_cast<std::uint32_t>(keep.b);
    m.start_i = 1;
    h_.tick();
    m.start_i = 0;
    FitOut o;
    o.clocks = 1;
    for (h_.eval(); !m.done_o && o.clocks < 1000; h_.eval()) {
      h_.tick();
      ++o.clocks;
    }
    auto i32 = [](std::uint32_t v) { return static_cast<std::int32_t>(v); };
    o.line = {static_cast<std::int32_t>(m.line_a_o), i32(m.line_b_o)};
    o.road.lo = {static_cast<std::int32_t>(m.road_lo_a_o), i32(m.road_lo_b_o)};
    o.road.hi = {static_cast<std::int32_t>(m.road_hi_a_o), i32(m.road_hi_b_o)};
    o.gate.lo = {static_cast<std::int32_t>(m.gate_lo_a_o), i32(m.gate_lo_b_o)};
    o.gate.hi = {static_cast<std::int32_t>(m.gate_hi_a_o), i32(m.gate_hi_b_o)};
    return o;
  }

 private:
  scw::sim::Harness<Vroad_fit> h_;
};

/// What one case came to, for the coverage checks: kept (and why) or fitted.
enum class Outcome { kFitted, kKept };

/// The engine against fit_line() and band() on one case; returns whether the road was fitted.
Outcome check_fit(FitRtl& rtl, const FitSums& s, const RoadConfig& c, const Line& keep,
                  int* max_clocks) {
  REQUIRE(s.n < (1u << 22));
  REQUIRE(s.sv < (1ull << 31));
  REQUIRE(s.svv < (1ull << 41));
  REQUIRE(s.sd < (1ull << 36));
  REQUIRE(s.svd < (1ull << 46));
  const Line want = scw::hls::road::fit_line(s, c, keep);
  const Band road = scw::hls::road::band(want, c.tol_q4, c.tol_rel_q8);
  const Band gate = scw::hls::road::band(want, c.gate_q4, c.gate_rel_q8);
  const FitOut o = rtl.run(s, c, keep);
  INFO("n " << s.n << " sv " << s.sv << " svv " << s.svv << " sd " << s.sd << " svd " << s.svd
            << " min_count " << c.min_count << " a " << c.a_min << " .. " << c.a_max << " h "
            << c.h_min << " .. " << c.h_max << " keep " << keep.a << ", " << keep.b);
  REQUIRE(o.clocks <= static_cast<int>(Vroad_fit_scw_road_fit::Clocks));
  *max_clocks = std::max(*max_clocks, o.clocks);
  CHECK(o.line.a == want.a);
  CHECK(o.line.b == want.b);
  CHECK(o.road.lo == road.lo);
  CHECK(o.road.hi == road.hi);
  CHECK(o.gate.lo == gate.lo);
  CHECK(o.gate.hi == gate.hi);
  return want == keep ? Outcome::kKept : Outcome::kFitted;
}

/// Sums of points near a line (a px a row from row `horizon`) in groups of one row and many
/// pixels, so n reaches 2^21 without that many points.
FitSums planted_sums(std::mt19937_64& rng, double a_px, double horizon, int groups,
                     int max_count, int noise_q4) {
  auto uni = [&rng](std::int64_t lo, std::int64_t hi) {
    return std::uniform_int_distribution<std::int64_t>(lo, hi)(rng);
  };
  FitSums s;
  for (int g = 0; g < groups; ++g) {
    const std::int64_t v = uni(std::max<std::int64_t>(0, std::llround(horizon) + 1), 1023);
    const std::int64_t c = uni(1, max_count);
    const std::int64_t d = std::llround(16 * a_px * (v - horizon));
    if (d - noise_q4 < 1 || d + noise_q4 > 0x7fff) continue;
    const std::int64_t sum_d = c * d + uni(-c * noise_q4, c * noise_q4);
    s.n += c;
    s.sv += c * v;
    s.svv += c * v * v;
    s.sd += sum_d;
    s.svd += v * sum_d;
  }
  return s;
}

/// A value of a random bit length up to `bits`, so that every magnitude occurs.
std::uint64_t random_bits(std::mt19937_64& rng, int bits) {
  const int len = std::uniform_int_distribution<int>(0, bits)(rng);
  return len == 0 ? 0 : rng() >> (64 - len);
}

Line random_keep(std::mt19937_64& rng) {
  const auto a = static_cast<std::int32_t>(random_bits(rng, 18));
  auto b = static_cast<std::int32_t>(rng());
  if (rng() % 2) b >>= std::uniform_int_distribution<int>(0, 31)(rng);
  return {a, b};
}

}  // namespace

TEST_CASE("scw_road_fit equals fit_line and band on planted, random and edge-case sums",
          "[road][rtl]") {
  FitRtl rtl;
  int max_clocks = 0, fitted = 0, kept = 0;
  auto count = [&](Outcome o) { (o == Outcome::kFitted ? fitted : kept) += 1; };

  SECTION("planted roads, configurations near them and anywhere") {
    std::mt19937_64 rng(11);
    for (int t = 0; t < 5000; ++t) {
      const double a_px = std::uniform_real_distribution<double>(0.05, 3.9)(rng);
      const double horizon = std::uniform_real_distribution<double>(-20, 600)(rng);
      const int groups = std::uniform_int_distribution<int>(1, 1024)(rng);
      const int max_count = 1 << std::uniform_int_distribution<int>(0, 11)(rng);
      const int noise = std::uniform_int_distribution<int>(0, 40)(rng);
      const FitSums s = planted_sums(rng, a_px, horizon, groups, max_count, noise);
      RoadConfig c;
      const double unit = 16.0 * 4096;
      const double spread = std::uniform_real_distribution<double>(1.0, 3.0)(rng);
      c.a_min = static_cast<std::int32_t>(std::min(262143.0, a_px / spread * unit));
      c.a_max = static_cast<std::int32_t>(std::min(262143.0, a_px * spread * unit));
      const int h_spread = std::uniform_int_distribution<int>(0, 40)(rng);
      c.h_min = static_cast<std::uint16_t>(std::clamp(horizon - h_spread, 0.0, 1023.0));
      c.h_max = static_cast<std::uint16_t>(std::clamp(horizon + h_spread, 0.0, 1023.0));
      c.min_count = static_cast<std::uint32_t>(
          std::min<std::uint64_t>((1u << 20) - 1, random_bits(rng, 21)));
      c.tol_q4 = static_cast<std::uint16_t>(random_bits(rng, 15));
      c.tol_rel_q8 = static_cast<std::uint8_t>(rng());
      c.gate_q4 = static_cast<std::uint16_t>(random_bits(rng, 15));
      c.gate_rel_q8 = static_cast<std::uint8_t>(rng());
      count(check_fit(rtl, s, c, random_keep(rng), &max_clocks));
    }
    CHECK(fitted > 1000);
    CHECK(kept > 1000);
  }

  SECTION("random sums over the ports' widths") {
    std::mt19937_64 rng(12);
    for (int t = 0; t < 5000; ++t) {
      FitSums s;
      s.n = random_bits(rng, 22);
      s.sv = random_bits(rng, 31);
      s.svv = random_bits(rng, 41);
      s.sd = random_bits(rng, 36);
      s.svd = random_bits(rng, 46);
      RoadConfig c;
      c.min_count = static_cast<std::uint32_t>(random_bits(rng, 20));
      c.a_min = static_cast<std::int32_t>(random_bits(rng, 18));
      c.a_max = static_cast<std::int32_t>(random_bits(rng, 18));
      if (rng() % 2) {
        c.a_min = 0;
        c.a_max = (1 << 18) - 1;
      }
      c.h_min = static_cast<std::uint16_t>(random_bits(rng, 10));
      c.h_max = static_cast<std::uint16_t>(random_bits(rng, 10));
      if (rng() % 2) {
        c.h_min = 0;
        c.h_max = 1023;
      }
      c.tol_q4 = static_cast<std::uint16_t>(random_bits(rng, 15));
      c.tol_rel_q8 = static_cast<std::uint8_t>(rng());
      c.gate_q4 = static_cast<std::uint16_t>(random_bits(rng, 15));
      c.gate_rel_q8 = static_cast<std::uint8_t>(rng());
      count(check_fit(rtl, s, c, random_keep(rng), &max_clocks));
    }
    CHECK(fitted > 30);
  }

  SECTION("edge cases: each check's boundary, the widest sums, the bands' wrap") {
    RoadConfig wide;
    wide.a_min = 0;
    wide.a_max = (1 << 18) - 1;
    wide.h_min = 0;
    wide.h_max = 1023;
    wide.min_count = 1;
    const Line keep{1234, -5678};
    std::vector<std::pair<FitSums, RoadConfig>> cases;
    auto add = [&](FitSums s, RoadConfig c) { cases.push_back({s, c}); };
    // n = 1, sv = 0: den = svv, num = svd, c = -sd 2^12, so sd = 0 gives -b = 0.
    for (std::uint64_t d : {1ull, 2ull, 4095ull, 4096ull, 4097ull, 123457ull, (1ull << 41) - 1}) {
      const std::uint64_t one = 1;
      for (std::uint64_t num : {64 * d - 1, 64 * d, 64 * d + 1, d, d - 1, one}) {
        if (num >= (1ull << 46)) continue;
        add({1, 0, d, 0, num}, wide);
        add({1, 0, d, 1, num}, wide);  // c < 0
      }
    }
    // n = 1, sd = 0: -b = a sv, on either bound of the horizon range and just outside.
    for (std::uint64_t v : {1ull, 7ull, 100ull, 1023ull, 1024ull, 5000ull, 1000000ull}) {
      for (int dh : {-1, 0, 1}) {
        RoadConfig c = wide;
        const std::int64_t h = std::clamp<std::int64_t>(static_cast<std::int64_t>(v) + dh, 0, 1023);
        c.h_min = c.h_max = static_cast<std::uint16_t>(h);
        add({1, v, v * v + 1000, 0, 70}, c);
        add({1, v, v * v + 1, 0, 64}, c);
      }
    }
    // den = 0 (one row), num = 0, n = 0, min_count on either side of n.
    add({2, 20, 200, 30, 300}, wide);
    add({3, 6, 14, 9, 18}, wide);
    add({0, 0, 0, 0, 0}, wide);
    add({0, 5, 100, 7, 900}, wide);
    for (std::uint32_t mc : {999u, 1000u, 1001u}) {
      RoadConfig c = wide;
      c.min_count = mc;
      FitSums s{1000, 1000 * 300, 1000 * 300 * 300 + 999, 1000 * 100, 1000 * 100 * 300 + 50};
      add(s, c);
      std::mt19937_64 rng(5);
      s = planted_sums(rng, 0.45, 10, 50, 20, 3);
      c.min_count = static_cast<std::uint32_t>(s.n) + mc - 1000;
      add(s, c);
    }
    // The widest sums the ports carry, and sums of a full 2048 x 1024 frame.
    add({(1u << 22) - 1, (1ull << 31) - 1, (1ull << 41) - 1, (1ull << 36) - 1, (1ull << 46) - 1},
        wide);
    add({(1u << 22) - 1, 1, (1ull << 41) - 1, 0, (1ull << 46) - 1}, wide);
    add({1u << 21, (1ull << 21) * 1023, (1ull << 21) * 1023 * 1023, (1ull << 21) * 0x7fff,
         (1ull << 21) * 1023 * 0x7fff}, wide);
    {
      std::mt19937_64 rng(9);
      add(planted_sums(rng, 3.9, 1.0, 1024, 2048, 0), wide);
      add(planted_sums(rng, 0.05, 500.0, 1024, 2048, 40), wide);
    }
    // The slope on a_min and a_max exactly.
    {
      std::mt19937_64 rng(3);
      const FitSums s = planted_sums(rng, 0.45, 12, 200, 30, 2);
      const Line l = scw::hls::road::fit_line(s, wide, keep);
      REQUIRE(l != keep);
      for (int da : {-1, 0, 1}) {
        RoadConfig c = wide;
        c.a_min = l.a + da;
        add(s, c);
        c = wide;
        c.a_max = l.a + da;
        add(s, c);
      }
    }
    for (const auto& [s, c] : cases) count(check_fit(rtl, s, c, keep, &max_clocks));
    // The bands of extreme roads (kept: no pixels), their sums wrapping at 32 bits as the C++
    // casts them.
    RoadConfig c = wide;
    c.min_count = 1;
    for (std::int32_t b : {std::numeric_limits<std::int32_t>::min(), -(1 << 30) + 1, -1, 0, 1,
                           (1 << 30) - 1, std::numeric_limits<std::int32_t>::max()}) {
      for (int rel : {0, 1, 128, 255}) {
        for (std::uint16_t t : {std::uint16_t{0}, std::uint16_t{1}, std::uint16_t{0x7fff}}) {
          c.tol_q4 = t;
          c.tol_rel_q8 = static_cast<std::uint8_t>(rel);
          c.gate_q4 = static_cast<std::uint16_t>(0x7fff - t);
          c.gate_rel_q8 = static_cast<std::uint8_t>(255 - rel);
          count(check_fit(rtl, FitSums{}, c, Line{(1 << 18) - 1, b}, &max_clocks));
          count(check_fit(rtl, FitSums{}, c, Line{0, b}, &max_clocks));
        }
      }
    }
    CHECK(fitted > 10);
  }
  // A plausible fit runs every step: the engine's Clocks is its longest run.
  if (fitted > 0) CHECK(max_clocks == static_cast<int>(Vroad_fit_scw_road_fit::Clocks));
}

TEST_CASE("scw_road equals the model clock for clock while the fits move the road",
          "[road][rtl]") {
  RoadScene scene = small_scene(1.2);
  scene.noise = 0.3;
  scene.objects = 2;
  const std::vector<std::pair<double, double>> starts = {{0.8, 2.0}, {1.3, -2.0}, {1.0, 0.0}};
  for (const auto& [slope_error, shift] : starts) {
    const RoadConfig cfg = scw::fixtures::road_config(scene, slope_error, shift, 20);
    DYNAMIC_SECTION("nominal slope x " << slope_error << ", horizon " << shift << " off") {
      const auto maps = road_maps(scene, 40, 5);
      SECTION("one disparity a beat") {
        const auto beats = map_beats<Params1>(maps);
        const auto t = trace_kernel<Params1>(beats, cfg);
        REQUIRE(roads_used(t) >= 3);  // the fits moved the road, more than once
        REQUIRE(t.zeroed > 500);
        check_beats<Vroad_p1, Params1>(beats, cfg);
      }
      SECTION("two disparities a beat") {
        const auto beats = map_beats<Params2>(maps);
        const auto t = trace_kernel<Params2>(beats, cfg);
        REQUIRE(roads_used(t) >= 3);
        REQUIRE(t.zeroed > 500);
        check_beats<Vroad_p2, Params2>(beats, cfg);
      }
    }
  }
  SECTION("four disparities a beat, 64 wide, frames taller than MaxHeight") {
    RoadScene wide = scene;
    wide.width = 64;
    wide.height = 20;
    wide.slope = 1.5;
    wide.horizon = 3;
    const RoadConfig cfg = scw::fixtures::road_config(wide, 0.85, 1.5, 20);
    auto maps = road_maps(wide, 60, 4);
    RoadScene tall = wide;
    tall.height = 26;  // rows past MaxHeight - 1 keep the last row's values
    maps.insert(maps.begin() + 2, scw::fixtures::road_map(tall, 77));
    const auto beats = map_beats<Params4>(maps);
    const auto t = trace_kernel<Params4>(beats, cfg);
    REQUIRE(roads_used(t) >= 3);
    REQUIRE(t.zeroed > 500);
    check_beats<Vroad_p4, Params4>(beats, cfg);
  }
  SECTION("disabled: every disparity passes, the road still fitted") {
    RoadConfig cfg = scw::fixtures::road_config(scene, 0.8, 2.0, 20);
    cfg.enable = false;
    const auto beats = map_beats<Params2>(road_maps(scene, 50, 3));
    const auto t = trace_kernel<Params2>(beats, cfg);
    REQUIRE(roads_used(t) >= 2);
    REQUIRE(t.zeroed == 0);
    check_beats<Vroad_p2, Params2>(beats, cfg);
  }
}

TEST_CASE("scw_road keeps its road when the fit is implausible, like the model",
          "[road][rtl]") {
  RoadScene scene = small_scene(1.0);
  scene.objects = 0;
  RoadConfig cfg = scw::fixtures::road_config(scene, 1.0, 0.0, 20);
  RoadScene wrong = scene;
  // A slope three times the nominal: its rows 5 and 6 fall in the gate, and give it back.
  SECTION("slope") { wrong.slope = 3.0; }
  // A horizon 10 rows lower, all of it in a wider gate: the fit finds it, below h_max.
  SECTION("horizon") {
    wrong.horizon = 14;
    cfg.gate_q4 = 16 * 12;
  }
  const auto beats = map_beats<Params1>(road_maps(wrong, 7, 4));
  // The gate takes enough pixels every frame, but their line is refused.
  scw::hls::road::Road<Params1> k(cfg);
  int fits = 0;
  for (const auto& b : beats) {
    if (k.needs_fit(b)) {
      if (fits++ > 0) REQUIRE(k.sums().n >= cfg.min_count);
      k.fit();
      REQUIRE(k.line() == cfg.nominal);
    }
    k.step(b);
  }
  REQUIRE(fits == 4);
  check_beats<Vroad_p1, Params1>(beats, cfg);
}

TEST_CASE("scw_road keeps its road when too few pixels are in the gate, like the model",
          "[road][rtl]") {
  RoadScene scene = small_scene(1.0);
  const RoadConfig cfg = scw::fixtures::road_config(scene, 0.9, 1.0, 5000);
  const auto beats = map_beats<Params2>(road_maps(scene, 3, 3));
  const auto t = trace_kernel<Params2>(beats, cfg);
  REQUIRE(roads_used(t) == 1);
  REQUIRE(t.lines.back() == cfg.nominal);
  REQUIRE(t.zeroed > 100);
  check_beats<Vroad_p2, Params2>(beats, cfg);
}

TEST_CASE("scw_road equals the model clock for clock on random maps of several sizes",
          "[road][rtl]") {
  // Full and narrower rows, rows of one beat, 1 x 1 frames (a sof that is also an eol, and a sof
  // right after a sof), frames taller than MaxHeight, random codes and configurations.
  const int sizes[][2] = {{32, 24}, {8, 30}, {1, 1}, {1, 1}, {4, 3}, {32, 1}, {2, 26}, {16, 12}};
  const int sizes4[][2] = {{64, 20}, {8, 23}, {4, 1}, {4, 1}, {8, 3}, {64, 1}, {4, 26}, {32, 12}};
  for (std::uint64_t seed : {1, 2, 3}) {
    std::mt19937_64 rng(seed);
    std::vector<cv::Mat> maps;
    for (const auto& wh : sizes) maps.push_back(random_map(wh[0], wh[1], rng));
    const RoadConfig cfg = random_config(rng);
    DYNAMIC_SECTION("seed " << seed << ", one disparity a beat") {
      check_beats<Vroad_p1, Params1>(map_beats<Params1>(maps), cfg);
    }
    std::vector<cv::Mat> maps4;
    for (const auto& wh : sizes4) maps4.push_back(random_map(wh[0], wh[1], rng));
    DYNAMIC_SECTION("seed " << seed << ", four disparities a beat") {
      check_beats<Vroad_p4, Params4>(map_beats<Params4>(maps4), cfg);
    }
  }
}

TEST_CASE("scw_road takes a beat a clock, and each fit holds a sof kFitClocks + 1 clocks",
          "[road][rtl]") {
  RoadScene scene = small_scene(1.2);
  const RoadConfig cfg = scw::fixtures::road_config(scene, 0.9, 1.0, 20);
  const auto beats = map_beats<Params2>(road_maps(scene, 90, 3));
  std::int64_t cycles = 0;
  run_twins<Vroad_p2, Params2>(beats, cfg, StallPattern{}, &cycles);
  CHECK(cycles == static_cast<std::int64_t>(beats.size()) +
                      3 * (scw::hls::road::kFitClocks + 1) + scw::hls::road::kLatency);
}

TEST_CASE("scw_road's widest row values: the extreme configuration check_config accepts",
          "[road][rtl]") {
  // The steepest nominal road at the highest intercept, the widest tolerances: the road band's
  // high edge starts near 5 x 2^27 and climbs by about 2^19 a row, the widest row values an
  // accepted configuration reaches; its low edge is negative, so every valid code is on the road.
  RoadConfig cfg;
  cfg.nominal = {static_cast<std::int32_t>(scw::hls::road::kMaxSlope),
                 static_cast<std::int32_t>(scw::hls::road::kMaxIntercept)};
  cfg.a_min = 0;
  cfg.a_max = static_cast<std::int32_t>(scw::hls::road::kMaxSlope);
  cfg.h_min = 0;
  cfg.h_max = 1023;
  cfg.tol_q4 = 0x7fff;
  cfg.tol_rel_q8 = 255;
  cfg.gate_q4 = 0x7fff;
  cfg.gate_rel_q8 = 255;
  cfg.min_count = 20;
  scw::hls::road::check_config(cfg);
  const Band road = scw::hls::road::band(cfg.nominal, cfg.tol_q4, cfg.tol_rel_q8);
  REQUIRE(road.hi.b > (std::int64_t{1} << 29));
  REQUIRE(road.lo.b < 0);
  std::mt19937_64 rng(4);
  std::vector<cv::Mat> maps;
  for (int f = 0; f < 3; ++f) maps.push_back(random_map(32, 24, rng));
  const auto beats = map_beats<Params1>(maps);
  const auto t = trace_kernel<Params1>(beats, cfg);
  REQUIRE(t.zeroed > 1000);
  check_beats<Vroad_p1, Params1>(beats, cfg);
}

namespace {

/// The stage with its line output between FIFOs (SideComponent, as the pipeline wires it), the
/// lines read slowly through a one-word FIFO so sofs wait for it. Returns the beats out, the
/// lines out and the cycles the run took.
template <typename M, typename Params>
std::tuple<std::vector<typename Params::out_beat>, std::vector<scw::hls::Packet<Line>>,
           std::int64_t>
run_lines(M model, const std::vector<typename Params::in_beat>& beats, std::size_t frames,
          const StallPattern& p) {
  using In = typename Params::in_beat;
  using Out = typename Params::out_beat;
  using L = scw::hls::Packet<Line>;
  scw::sim::Simulator s;
  auto& in = s.fifo<In>("in", 2);
  auto& out = s.fifo<Out>("out", 2);
  auto& lines = s.fifo<L>("lines", 1);
  auto& src = s.add<scw::sim::Source<In>>("source", in, beats, p);
  s.add<scw::sim::SideComponent<M>>("road", std::move(model), in, out, lines);
  auto& sink = s.add<scw::sim::Sink<Out>>("sink", out, p);
  auto& lsink = s.add<scw::sim::Sink<L>>("line_sink", lines, StallPattern::parse("random:9"));
  s.run_until([&] { return src.done() && sink.beats().size() == beats.size() &&
                           lsink.beats().size() == frames; },
              2'000'000);
  return {sink.beats(), lsink.beats(), s.cycle()};
}

}  // namespace

TEST_CASE("scw_road's line output: each frame's road, read with backpressure, like the model",
          "[road][rtl]") {
  RoadScene scene = small_scene(1.2);
  scene.noise = 0.3;
  scene.objects = 2;
  const RoadConfig cfg = scw::fixtures::road_config(scene, 0.8, 2.0, 20);
  const auto maps = road_maps(scene, 40, 5);
  const auto beats = map_beats<Params2>(maps);
  const auto t = trace_kernel<Params2>(beats, cfg);
  REQUIRE(roads_used(t) >= 3);
  REQUIRE(t.lines.size() == maps.size());  // one fit (or the nominal road) at each sof
  std::vector<typename Params2::out_beat> want(beats.size());
  scw::hls::road::Road<Params2> k(cfg);
  scw::hls::road::road_frame(k, beats.data(), want.data(), static_cast<int>(beats.size()));
  for (const auto& pattern : {StallPattern{}, StallPattern::parse("random:3")}) {
    INFO("stalls " << pattern.name());
    const auto [cb, cl, cc] = run_lines<scw::sim::RoadModel<Params2>, Params2>(
        scw::sim::RoadModel<Params2>(cfg), beats, maps.size(), pattern);
    const auto [rb, rl, rc] = run_lines<scw::sim::RoadSideRtl<Vroad_p2, Params2>, Params2>(
        scw::sim::RoadSideRtl<Vroad_p2, Params2>("road_lines", cfg), beats, maps.size(),
        pattern);
    CHECK(cc == rc);  // the same cycles, with sofs held for the line register
    CHECK(cb == want);
    CHECK(rb == want);
    REQUIRE(cl.size() == t.lines.size());
    REQUIRE(rl.size() == t.lines.size());
    for (std::size_t f = 0; f < t.lines.size(); ++f) {
      INFO("frame " << f);
      CHECK(cl[f].data == t.lines[f]);
      CHECK(rl[f].data == t.lines[f]);
      CHECK(rl[f].last);
    }
  }
}
