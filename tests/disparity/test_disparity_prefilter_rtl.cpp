// SPDX-License-Identifier: Apache-2.0
// scw_disparity_prefilter against hls::disparity::XSobel clock for clock: the same allowed flags
// every clock and the same beats kReadLatency clocks after each read, frames back to back.
#include <catch2/catch.hpp>
#include <cstdint>
#include <deque>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "hls/disparity/disparity_params.hpp"
#include "hls/disparity/prefilter.hpp"
#include "host/reference/disparity_ref.hpp"
#include "sim/core/frame_beats.hpp"
#include "sim/rtl/verilated_harness.hpp"
#include "Vprefilter_p1.h"
#include "Vprefilter_p1_scw_disparity_prefilter.h"
#include "Vprefilter_p2.h"
#include "Vprefilter_p2_scw_disparity_prefilter.h"
#include "Vprefilter_p4.h"
#include "Vprefilter_p4_scw_disparity_prefilter.h"

namespace {

using namespace scw;

// As tests/disparity/prefilter_rtl.cmake passes them to Verilator.
constexpr int kMaxWidthPx = 32;
constexpr int kMaxHeight = 16;

// XSobel reads only kPpc, kMaxWidthPx and pixel_beat; the window and candidates are filler.
template <int P>
using PrefilterParams = hls::disparity::DisparityParams<P, kMaxWidthPx, 3, 2>;
template <int P>
using XSobel = hls::disparity::XSobel<PrefilterParams<P>>;

template <typename VM, int P>
constexpr bool params_match() {
  return static_cast<int>(VM::Ppc) == P && static_cast<int>(VM::MaxWidthPx) == kMaxWidthPx &&
         static_cast<int>(VM::MaxHeight) == kMaxHeight &&
         static_cast<int>(VM::Latency) == XSobel<P>::kReadLatency;
}
static_assert(params_match<Vprefilter_p1_scw_disparity_prefilter, 1>());
static_assert(params_match<Vprefilter_p2_scw_disparity_prefilter, 2>());
static_assert(params_match<Vprefilter_p4_scw_disparity_prefilter, 4>());

/// Per clock, the chance (in %) that an allowed write or read is issued; `pause` adds
/// verilog-axis' [1, 1, 1, 0] pattern on top (the writer skips every 4th clock, the reader
/// another one).
struct Pace {
  const char* name;
  int wr_pct, rd_pct;
  bool pause = false;
};
const Pace kPaces[] = {
    {"no stalls", 100, 100}, {"idle input", 55, 100},           {"reader backpressure", 100, 45},
    {"both", 50, 50},        {"pause pattern", 100, 100, true},
};

struct Geometry {
  int width, height, cap, frames;
};

std::string describe(const Geometry& g) {
  std::ostringstream s;
  s << g.width << " x " << g.height << ", cap " << g.cap << ", " << g.frames << " frames";
  return s.str();
}

/// Full-range noise (sums far outside every cap) or, every other frame, low-contrast noise
/// (sums inside the cap, so the unclamped values show).
std::vector<std::uint8_t> random_image(int w, int h, int frame, std::mt19937_64& rng) {
  std::vector<std::uint8_t> img(static_cast<std::size_t>(w * h));
  const bool low = frame % 2 == 1;
  for (auto& v : img)
    v = static_cast<std::uint8_t>(low ? 120 + static_cast<int>(rng() % 12)
                                      : static_cast<int>(rng() % 256));
  return img;
}

template <typename Beat>
std::uint32_t pack(const Beat& b) {
  std::uint32_t v = 0;
  for (int i = 0; i < Beat::kPixels; ++i)
    v |= static_cast<std::uint32_t>(b.px[static_cast<std::size_t>(i)]) << (8 * i);
  return v;
}

/// Clocks RTL and twin side by side over `g.frames` random frames under `pace`; returns the
/// number of mismatches (and describes the first). The twin's beats must also equal the
/// direct reference, frame by frame.
template <typename VM, int P>
void check_twins(const Geometry& g, const Pace& pace, std::uint64_t seed) {
  using Beat = typename PrefilterParams<P>::pixel_beat;
  constexpr std::uint64_t kLatency = XSobel<P>::kReadLatency;
  std::mt19937_64 rng(seed);

  std::vector<Beat> in;
  std::vector<std::uint8_t> ref;
  for (int f = 0; f < g.frames; ++f) {
    const auto img = random_image(g.width, g.height, f, rng);
    const auto beats = sim::frame_beats<P>(img.data(), g.width, g.height);
    in.insert(in.end(), beats.begin(), beats.end());
    const auto r = reference::prefilter_xsobel_reference(img.data(), g.width, g.height, g.cap);
    ref.insert(ref.end(), r.begin(), r.end());
  }

  XSobel<P> twin;
  twin.configure(g.width, g.height, g.cap);
  sim::Harness<VM> h("prefilter_p" + std::to_string(P));
  auto& d = h.dut();
  d.cfg_width_i = static_cast<std::uint8_t>(g.width);
  d.cfg_height_i = static_cast<std::uint8_t>(g.height);
  d.cfg_cap_i = static_cast<std::uint8_t>(g.cap);
  d.wr_i = 0;
  d.rd_i = 0;
  d.wr_data_i = 0;
  h.reset();

  std::deque<std::pair<std::uint64_t, Beat>> due;  // read beats by the clock they leave the RTL
  std::vector<std::uint8_t> twin_px;
  std::size_t next_in = 0, outs = 0, errors = 0;
  std::string first_error;
  std::uint64_t clock = 0;
  const auto fail = [&](const std::string& what) {
    if (errors++ == 0) first_error = "clock " + std::to_string(clock) + ": " + what;
  };
  const std::uint64_t limit = 40 * in.size() + 200;
  while (outs < in.size() && clock < limit) {
    h.eval();
    const bool wa = twin.write_allowed(), ra = twin.read_allowed();
    if (static_cast<bool>(d.wr_allowed_o) != wa) fail("wr_allowed_o differs from write_allowed()");
    if (static_cast<bool>(d.rd_allowed_o) != ra) fail("rd_allowed_o differs from read_allowed()");
    const bool wr_gap = pace.pause && clock % 4 == 3, rd_gap = pace.pause && clock % 4 == 1;
    const bool wr =
        wa && next_in < in.size() && !wr_gap && static_cast<int>(rng() % 100) < pace.wr_pct;
    const bool rd = ra && !rd_gap && static_cast<int>(rng() % 100) < pace.rd_pct;
    d.wr_i = wr;
    d.rd_i = rd;
    // Idle data is noise: nothing may depend on wr_data_i without wr_i.
    d.wr_data_i = wr ? pack(in[next_in]) : static_cast<std::uint32_t>(rng());
    // Twin: allowed flags from the state before the edge, then read, then write (read-first).
    if (rd) {
      const Beat b = twin.read();
      due.emplace_back(clock + kLatency, b);
      twin_px.insert(twin_px.end(), b.px.begin(), b.px.end());
    }
    if (wr) twin.write(in[next_in++]);
    h.tick();
    ++clock;
    const bool expect = !due.empty() && due.front().first == clock;
    if (static_cast<bool>(d.out_valid_o) != expect) fail("out_valid_o is not rd_i delayed");
    if (!expect) continue;
    const Beat& b = due.front().second;
    for (int i = 0; i < P; ++i) {
      const int got = static_cast<int>((d.out_data_o >> (8 * i)) & 0xffu);
      const int want = b.px[static_cast<std::size_t>(i)];
      if (got != want) {
        fail("beat " + std::to_string(outs) + " lane " + std::to_string(i) + ": RTL " +
             std::to_string(got) + ", XSobel " + std::to_string(want));
      }
    }
    due.pop_front();
    ++outs;
  }
  // Nothing more may come out once every read has.
  for (int i = 0; i < 8; ++i) {
    d.wr_i = 0;
    d.rd_i = 0;
    h.tick();
    ++clock;
    if (d.out_valid_o) fail("out_valid_o without a read");
  }
  INFO(describe(g) << ", " << pace.name << ", seed " << seed << ", " << clock << " clocks");
  INFO(first_error);
  CHECK(outs == in.size());
  CHECK(errors == 0);
  CHECK(twin_px == ref);
}

template <typename VM, int P>
void check_geometries(const std::vector<Geometry>& geometries) {
  std::uint64_t seed = 1000 * P;
  for (const auto& g : geometries) {
    for (const auto& pace : kPaces) {
      ++seed;
      DYNAMIC_SECTION(describe(g) << ", " << pace.name) { check_twins<VM, P>(g, pace, seed); }
    }
  }
}

/// Widths 32 (MaxWidthPx), 8, 2P and P (one beat per row); heights 16 (MaxHeight), 15 and 3
/// (odd: the cap row), 2 and 1; caps 1, 31 and 63 spread over them.
template <int P>
std::vector<Geometry> geometries() {
  return {{32, 16, 31, 5}, {32, 15, 63, 5},    {32, 16, 1, 4},   {8, 3, 31, 8},
          {8, 2, 63, 8},   {2 * P, 16, 31, 5}, {2 * P, 5, 1, 6}, {P, 4, 31, 6},
          {P, 1, 63, 8},   {8, 1, 1, 8},       {32, 2, 31, 6},   {2 * P, 15, 63, 4}};
}

}  // namespace

TEST_CASE("scw_disparity_prefilter equals XSobel clock for clock, P = 1", "[disparity][rtl]") {
  check_geometries<Vprefilter_p1, 1>(geometries<1>());
}
TEST_CASE("scw_disparity_prefilter equals XSobel clock for clock, P = 2", "[disparity][rtl]") {
  check_geometries<Vprefilter_p2, 2>(geometries<2>());
}
TEST_CASE("scw_disparity_prefilter equals XSobel clock for clock, P = 4", "[disparity][rtl]") {
  check_geometries<Vprefilter_p4, 4>(geometries<4>());
}
