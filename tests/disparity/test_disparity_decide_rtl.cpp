// SPDX-License-Identifier: Apache-2.0
// scw_disparity_decide against decide<NumDisp>() cycle by cycle: a new input every clock, shaped
// to sit on every rule's boundary, under every combination of the rules, at 8 and 45 candidates.
#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cstdint>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include "Vdecide_n45.h"
#include "Vdecide_n45_scw_disparity_decide.h"
#include "Vdecide_n8.h"
#include "Vdecide_n8_scw_disparity_decide.h"
#include "hls/disparity/decide_latency.hpp"
#include "hls/disparity/disparity.hpp"
#include "sim/rtl/verilated_harness.hpp"

namespace {

using namespace scw;
using hls::disparity::candidates;
using hls::disparity::decide;
using hls::disparity::disp_t;
using hls::disparity::DisparityConfig;
using hls::disparity::invalid_code;
using hls::disparity::sad_t;

/// The parameters tests/disparity/decide_rtl.cmake builds each model with.
template <int NumDisp, int SadBits>
struct DecideParams {
  static constexpr int kNumDisp = NumDisp;
  static constexpr int kSadBits = SadBits;
  static constexpr int kDminBits = 8;
  static constexpr int kLatency = hls::disparity::decide_latency(NumDisp);
  static constexpr sad_t kMaxSad = (sad_t{1} << SadBits) - 1;
  /// cfg_num_i is $clog2(NumDisp + 1) bits wide: every value it can hold is tried.
  static constexpr int kNumPortMax = (2 << (32 - __builtin_clz(NumDisp) - 1)) - 1;
};
using N8 = DecideParams<8, 12>;
using N45 = DecideParams<45, 17>;

template <typename VM, typename P>
constexpr bool decide_params_match() {
  return static_cast<int>(VM::NumDisp) == P::kNumDisp &&
         static_cast<int>(VM::SadBits) == P::kSadBits &&
         static_cast<int>(VM::DminBits) == P::kDminBits &&
         static_cast<int>(VM::Latency) == P::kLatency;
}
static_assert(decide_params_match<Vdecide_n8_scw_disparity_decide, N8>());
static_assert(decide_params_match<Vdecide_n45_scw_disparity_decide, N45>());
static_assert(N8::kNumPortMax == 15 && N45::kNumPortMax == 63);

std::uint32_t pick(std::mt19937_64& rng, std::uint32_t lo, std::uint32_t hi) {
  return lo >= hi ? lo : std::uniform_int_distribution<std::uint32_t>(lo, hi)(rng);
}
bool chance(std::mt19937_64& rng, std::uint32_t percent) { return pick(rng, 0, 99) < percent; }

template <int N>
struct Pixel {
  bool valid = false;
  bool region = false;
  int limit = N;  // candidates inside the right image (decide()'s limit): fewer at the left edge
  std::array<sad_t, N> sad{};
  sad_t texture = 0;
};

/// What the inputs exercised, counted where the rule in question decides the output (nothing
/// before it rejected the pixel): the boundaries must all be hit, or the test proves little.
struct Coverage {
  long ties = 0, best_first = 0, best_last = 0, garbage_below = 0, all_max = 0, region_off = 0;
  long lim_at = 0, lim_above = 0, tex_at = 0, tex_below = 0;
  long uniq_at = 0, uniq_above = 0, near_below = 0, uniq_prod_max = 0;
  long fit = 0, fit_q128 = 0, fit_down = 0, fit_flat = 0, fit_exact = 0, n_one = 0;
  long edge = 0, edge_best_last = 0, edge_garbage_below = 0;  // a limit below the candidates
};

template <typename P>
void observe(const Pixel<P::kNumDisp>& px, const DisparityConfig& cfg, Coverage& c) {
  const auto& s = px.sad;
  const int n = std::min(candidates<P::kNumDisp>(cfg), px.limit);
  int best = 0;
  for (int d = 1; d < n; ++d)
    if (s[d] < s[best]) best = d;
  const sad_t m = s[best];
  int at_min = 0;
  bool all_max = true;
  for (int d = 0; d < n; ++d) {
    at_min += s[d] == m ? 1 : 0;
    all_max = all_max && s[d] == P::kMaxSad;
  }
  bool garbage_below = false;
  for (int d = n; d < P::kNumDisp; ++d) garbage_below = garbage_below || s[d] < m;
  c.ties += at_min > 1 ? 1 : 0;
  c.best_first += n > 1 && best == 0 ? 1 : 0;
  c.best_last += n > 1 && best == n - 1 ? 1 : 0;
  c.garbage_below += garbage_below ? 1 : 0;
  c.all_max += all_max ? 1 : 0;
  c.n_one += n == 1 ? 1 : 0;
  if (px.limit < candidates<P::kNumDisp>(cfg)) {
    ++c.edge;
    c.edge_best_last += n > 1 && best == n - 1 ? 1 : 0;
    c.edge_garbage_below += garbage_below ? 1 : 0;
  }
  if (!px.region) {
    ++c.region_off;
    return;
  }
  if (cfg.sad_limit > 0) {
    const auto lim = static_cast<sad_t>(cfg.sad_limit);
    c.lim_at += m == lim ? 1 : 0;
    c.lim_above += m == lim + 1 ? 1 : 0;
    if (m > lim) return;
  }
  if (cfg.texture_threshold > 0) {
    const auto thr = static_cast<sad_t>(cfg.texture_threshold);
    c.tex_at += px.texture == thr ? 1 : 0;
    c.tex_below += px.texture + 1 == thr ? 1 : 0;
    if (px.texture < thr) return;
  }
  if (cfg.uniqueness_ratio > 0) {
    const sad_t thresh = m + m * static_cast<sad_t>(cfg.uniqueness_ratio) / 100;
    sad_t far_min = std::numeric_limits<sad_t>::max();
    bool near = false;
    for (int d = 0; d < n; ++d) {
      if (d < best - 1 || d > best + 1) far_min = std::min(far_min, s[d]);
      if ((d == best - 1 || d == best + 1) && s[d] <= thresh) near = true;
    }
    c.uniq_at += far_min == thresh ? 1 : 0;
    c.uniq_above += far_min == thresh + 1 ? 1 : 0;
    c.near_below += near && far_min > thresh && far_min != std::numeric_limits<sad_t>::max();
    c.uniq_prod_max += m == P::kMaxSad && cfg.uniqueness_ratio == 255 ? 1 : 0;
    if (far_min <= thresh) return;
  }
  if (!cfg.subpixel || best == 0 || best == n - 1) return;
  ++c.fit;
  const sad_t prev = s[best - 1], next = s[best + 1];
  c.fit_q128 += next == m ? 1 : 0;
  c.fit_flat += prev == next ? 1 : 0;
  // frac = 16 k + 1 exactly: the last quotient bit alone decides the rounding up.
  const sad_t diff = prev > next ? prev - next : next - prev, den = 2 * (std::max(prev, next) - m);
  c.fit_exact += prev > next && diff * 256 % den == 0 && diff * 256 / den % 16 == 1 ? 1 : 0;
  c.fit_down += prev < next && decide<P::kNumDisp>(s, px.texture, cfg, px.limit) <
                                   static_cast<disp_t>((cfg.dmin + best) * 16)
                    ? 1
                    : 0;
}

/// One input: valid and region random, a third at the left edge (a limit below the candidates
/// in use), the SADs from one of several shapes, the candidates beyond n garbage (often below
/// the minimum), the texture often on the threshold.
template <typename P>
Pixel<P::kNumDisp> make_pixel(const DisparityConfig& cfg, std::mt19937_64& rng) {
  constexpr int N = P::kNumDisp;
  constexpr sad_t max = P::kMaxSad;
  Pixel<N> px;
  if (chance(rng, 33)) px.limit = static_cast<int>(pick(rng, 1, N));
  const int n = std::min(candidates<N>(cfg), px.limit);
  const auto uni = [&](sad_t lo, sad_t hi) {
    return pick(rng, std::min(lo, max), std::min(hi, max));
  };
  // Everything but s[best] strictly above m, except ties where a shape wants them.
  const auto place_min = [&](Pixel<N>& p, int best, sad_t m, bool ties) {
    for (int d = 0; d < n; ++d) p.sad[d] = uni(ties ? m : m + 1, max);
    p.sad[best] = m;
  };
  px.valid = chance(rng, 75);
  px.region = chance(rng, 90);
  for (auto& s : px.sad) s = uni(0, max);
  switch (pick(rng, 0, 9)) {
    case 0:  // uniform
      break;
    case 1: {  // many ties
      const sad_t base = uni(0, max - 2);
      for (auto& s : px.sad) s = base + uni(0, 2);
      break;
    }
    case 2: {  // flat
      const sad_t v = chance(rng, 30) ? 0 : chance(rng, 40) ? max : uni(0, max);
      for (auto& s : px.sad) s = v;
      break;
    }
    case 3:  // the largest SADs, sometimes one a step below
      for (auto& s : px.sad) s = max;
      if (chance(rng, 50)) px.sad[pick(rng, 0, static_cast<std::uint32_t>(n - 1))] = max - 1;
      break;
    case 4: {  // the minimum on the first or the last candidate in use
      place_min(px, chance(rng, 50) ? 0 : n - 1, uni(0, max - 1), chance(rng, 30));
      break;
    }
    case 5: {  // sub-pixel shapes around an inner minimum
      if (n < 3) break;
      const int best = static_cast<int>(pick(rng, 1, static_cast<std::uint32_t>(n - 2)));
      const sad_t m = uni(0, max / 2);
      place_min(px, best, m, false);
      const sad_t room = max - m;
      sad_t a = uni(1, room), b = uni(0, room);  // prev = m + a > m, next = m + b >= m
      switch (pick(rng, 0, 6)) {
        case 0:  // diff = 0
          b = a;
          break;
        case 1:  // next on the minimum: frac = 128
          b = 0;
          break;
        case 2:  // steep right side
          a = 1;
          break;
        case 3:  // steep left side
          b = 1;
          break;
        case 4:  // diff = +-1
          b = a + 1 <= room ? a + 1 : a - 1;
          break;
        case 5: {  // |diff| * 128 = q mx exactly or off by one: where the rounding turns
          const sad_t j = uni(1, room / 128), mx = 128 * j;
          const sad_t q = chance(rng, 50) ? 16 * pick(rng, 0, 7) + 1 : pick(rng, 0, 128);
          const int off = chance(rng, 50) ? 0 : static_cast<int>(pick(rng, 0, 2)) - 1;
          const auto diff = static_cast<sad_t>(
              std::clamp(static_cast<int>(q * j) + off, 0, static_cast<int>(mx)));
          if (chance(rng, 50)) {
            a = mx;
            b = mx - std::min(diff, mx);
          } else {
            b = mx;
            a = mx - std::min(diff, mx - 1);
          }
          break;
        }
        default:
          break;
      }
      px.sad[best - 1] = m + a;
      px.sad[best + 1] = m + b;
      break;
    }
    case 6: {  // uniqueness: a far candidate on thresh or just above, neighbours below it
      const sad_t u = cfg.uniqueness_ratio > 0 ? static_cast<sad_t>(cfg.uniqueness_ratio) : 15;
      const sad_t m = chance(rng, 10) ? max : uni(0, max / 4);
      const sad_t thresh = m + m * u / 100;
      const int best = static_cast<int>(pick(rng, 0, static_cast<std::uint32_t>(n - 1)));
      for (int d = 0; d < n; ++d) px.sad[d] = uni(thresh + 2, max);
      px.sad[best] = m;
      if (best > 0) px.sad[best - 1] = uni(m + 1, thresh);
      if (best + 1 < n) px.sad[best + 1] = uni(m, thresh);
      std::vector<int> far;
      for (int d = 0; d < n; ++d)
        if (d < best - 1 || d > best + 1) far.push_back(d);
      if (!far.empty() && chance(rng, 80)) {
        const int d = far[pick(rng, 0, static_cast<std::uint32_t>(far.size() - 1))];
        px.sad[d] = std::min(thresh + pick(rng, 0, 1), max);
      }
      break;
    }
    case 7: {  // the minimum on the SAD limit or a step off it
      if (cfg.sad_limit <= 0 || static_cast<sad_t>(cfg.sad_limit) > max) break;
      const auto lim = static_cast<sad_t>(cfg.sad_limit);
      const sad_t m = std::min(lim - 1 + pick(rng, 0, 2), max);
      place_min(px, static_cast<int>(pick(rng, 0, static_cast<std::uint32_t>(n - 1))), m,
                chance(rng, 20));
      break;
    }
    case 8:  // a small range: ties, small differences, small fractions
      for (auto& s : px.sad) s = uni(0, 15);
      break;
    default: {  // a random minimum with random neighbours
      place_min(px, static_cast<int>(pick(rng, 0, static_cast<std::uint32_t>(n - 1))), uni(0, max),
                chance(rng, 20));
      break;
    }
  }
  // Garbage beyond the candidates in use, often below every candidate in use.
  if (chance(rng, 50))
    for (int d = n; d < N; ++d) px.sad[d] = chance(rng, 50) ? 0 : uni(0, max);
  px.texture = uni(0, max);
  if (cfg.texture_threshold > 0 && static_cast<sad_t>(cfg.texture_threshold) <= max + 1 &&
      chance(rng, 50))
    px.texture = std::min(static_cast<sad_t>(cfg.texture_threshold) - 1 + pick(rng, 0, 2), max);
  return px;
}

/// The rules on or off by the bits of `combo` (SAD limit, texture, uniqueness, sub-pixel, invalid
/// code (dmin - 1) * 16 instead of 0, dmin 20 instead of 0); the values of the rules that are on
/// drawn from edge values and random ones; num_disp from `num`, any value cfg_num_i can hold.
template <typename P>
DisparityConfig make_config(int combo, int rep, int num, std::mt19937_64& rng) {
  constexpr auto max = static_cast<int>(P::kMaxSad);
  constexpr int kIntMax = std::numeric_limits<int>::max();
  const auto from = [&](std::initializer_list<int> v) {
    return *(v.begin() + pick(rng, 0, static_cast<std::uint32_t>(v.size() - 1)));
  };
  // A negative limit or threshold is off too (the int fields behind the 32-bit ports), also
  // one whose low bits look like a small positive value.
  const auto off = [&] {
    if (chance(rng, 75)) return 0;
    return chance(rng, 50) ? -static_cast<int>(pick(rng, 1, 1000))
                           : std::numeric_limits<int>::min() + static_cast<int>(pick(rng, 0, max));
  };
  DisparityConfig cfg;
  cfg.num_disp = num;
  cfg.sad_limit = (combo & 1)
                      ? from({static_cast<int>(pick(rng, 1, max)),
                              static_cast<int>(pick(rng, 1, max / 8)), 1, max, max + 1, kIntMax})
                      : off();
  cfg.texture_threshold =
      (combo & 2) ? from({static_cast<int>(pick(rng, 1, max)), static_cast<int>(pick(rng, 1, max)),
                          1, max, max + 1, max + 2, kIntMax})
                  : off();
  cfg.uniqueness_ratio =
      (combo & 4) ? from({1, 15, 99, 100, 255, static_cast<int>(pick(rng, 1, 255))}) : 0;
  cfg.subpixel = (combo & 8) != 0;
  cfg.opencv_invalid = (combo & 16) != 0;
  // dmin 0 and 20 as asked, and the extremes of an 8-bit cfg_dmin_i in one run of four.
  cfg.dmin = (combo & 32) ? (rep == 3 ? 255 : 20) : (rep == 3 ? 1 : 0);
  return cfg;
}

template <typename VM, typename P>
void drive(VM& dut, const DisparityConfig& cfg) {
  dut.cfg_num_i = static_cast<std::uint8_t>(cfg.num_disp);
  dut.cfg_dmin_i = static_cast<std::uint8_t>(cfg.dmin);
  dut.cfg_sad_limit_i = static_cast<std::uint32_t>(cfg.sad_limit);
  dut.cfg_texture_i = static_cast<std::uint32_t>(cfg.texture_threshold);
  dut.cfg_uniqueness_i = static_cast<std::uint8_t>(cfg.uniqueness_ratio);
  dut.cfg_subpixel_i = cfg.subpixel ? 1 : 0;
  dut.cfg_invalid_i = invalid_code(cfg);
}

template <typename VM, typename P>
void drive(VM& dut, const Pixel<P::kNumDisp>& px) {
  constexpr int kWords = (P::kNumDisp * P::kSadBits + 31) / 32;
  static_assert(sizeof(dut.sad_i) == kWords * sizeof(std::uint32_t));
  std::array<std::uint32_t, kWords + 1> w{};
  for (int d = 0; d < P::kNumDisp; ++d) {
    const int bit = d * P::kSadBits;
    const std::uint64_t v = static_cast<std::uint64_t>(px.sad[d]) << (bit % 32);
    w[bit / 32] |= static_cast<std::uint32_t>(v);
    w[bit / 32 + 1] |= static_cast<std::uint32_t>(v >> 32);
  }
  for (int i = 0; i < kWords; ++i) dut.sad_i.at(i) = w[i];
  dut.texture_i = px.texture;
  dut.valid_i = px.valid ? 1 : 0;
  dut.region_i = px.region ? 1 : 0;
  // The band mask as scw_disparity forms it: bit d = d < limit.
  constexpr int kBandWords = (P::kNumDisp + 31) / 32;
  std::array<std::uint32_t, kBandWords> band{};
  for (int d = 0; d < std::min(px.limit, P::kNumDisp); ++d) band[d / 32] |= 1u << (d % 32);
  static_assert(kBandWords <= 2, "band_i is at most 64 bits here");
  const std::uint64_t mask = kBandWords == 1
                                 ? band[0]
                                 : static_cast<std::uint64_t>(band[0]) |
                                       static_cast<std::uint64_t>(band[kBandWords - 1]) << 32;
  dut.band_i = static_cast<std::remove_reference_t<decltype(dut.band_i)>>(mask);
  dut.limit_i = static_cast<std::uint8_t>(px.limit);
}

template <typename P>
std::string describe(const DisparityConfig& cfg, const Pixel<P::kNumDisp>& px) {
  std::ostringstream o;
  o << "num_disp " << cfg.num_disp << " dmin " << cfg.dmin << " sad_limit " << cfg.sad_limit
    << " texture_threshold " << cfg.texture_threshold << " uniqueness " << cfg.uniqueness_ratio
    << " subpixel " << cfg.subpixel << " opencv_invalid " << cfg.opencv_invalid << "\n  valid "
    << px.valid << " region " << px.region << " limit " << px.limit << " texture " << px.texture
    << "\n  sad";
  for (const auto s : px.sad) o << ' ' << s;
  return o.str();
}

struct Tally {
  long cycles = 0;      // outputs compared
  long mismatches = 0;  // valid_o or disp_o wrong
  std::string first;    // the first mismatch, described
};

/// One configuration: reset (the configuration registers load meanwhile), then `cycles` inputs
/// back to back, each output compared Latency clocks after its input; valid_o low until then.
template <typename VM, typename P>
void run(sim::Harness<VM>& h, const DisparityConfig& cfg, int cycles, std::mt19937_64& rng,
         Coverage& cov, Tally& tally) {
  constexpr int L = P::kLatency;
  struct Expect {
    bool valid;
    disp_t disp;
  };
  auto& dut = h.dut();
  drive<VM, P>(dut, cfg);
  dut.valid_i = 0;
  h.reset(2);
  std::vector<Pixel<P::kNumDisp>> in;
  std::vector<Expect> expect;
  in.reserve(static_cast<std::size_t>(cycles));
  expect.reserve(static_cast<std::size_t>(cycles));
  for (int t = 0; t < cycles + L; ++t) {
    const bool got_valid = dut.valid_o != 0;
    const auto got = static_cast<disp_t>(dut.disp_o);
    if (t >= L) {
      const Expect& e = expect[static_cast<std::size_t>(t - L)];
      ++tally.cycles;
      if (got_valid != e.valid || got != e.disp) {
        if (tally.mismatches++ == 0) {
          std::ostringstream o;
          o << describe<P>(cfg, in[static_cast<std::size_t>(t - L)]) << "\n  expected valid "
            << e.valid << " disp " << e.disp << ", got valid " << got_valid << " disp " << got;
          tally.first = o.str();
        }
      }
    } else if (got_valid) {
      if (tally.mismatches++ == 0) tally.first = "valid_o high before Latency clocks";
    }
    if (t < cycles) {
      const auto px = make_pixel<P>(cfg, rng);
      drive<VM, P>(dut, px);
      observe<P>(px, cfg, cov);
      in.push_back(px);
      expect.push_back({px.valid, px.region ? decide<P::kNumDisp>(px.sad, px.texture, cfg, px.limit)
                                            : invalid_code(cfg)});
    } else {
      dut.valid_i = 0;
    }
    h.tick();
  }
}

/// Every combination of the rules, four drawings of their values each, every cfg_num_i value.
template <typename VM, typename P>
void check_decide(const char* name, int cycles_per_run, std::uint64_t seed) {
  sim::Harness<VM> h(name);
  std::mt19937_64 rng(seed);
  Coverage cov;
  Tally tally;
  int run_index = 0;
  for (int combo = 0; combo < 64; ++combo) {
    for (int rep = 0; rep < 4; ++rep, ++run_index) {
      const int num = run_index % (P::kNumPortMax + 1);
      const DisparityConfig cfg = make_config<P>(combo, rep, num, rng);
      run<VM, P>(h, cfg, cycles_per_run, rng, cov, tally);
    }
  }
  INFO("first mismatch: " << tally.first);
  CHECK(tally.mismatches == 0);
  CHECK(tally.cycles == 64L * 4 * cycles_per_run);
  INFO("coverage: ties " << cov.ties << ", best first " << cov.best_first << ", best last "
                         << cov.best_last << ", garbage below " << cov.garbage_below << ", all max "
                         << cov.all_max << ", n = 1 " << cov.n_one << ", region off "
                         << cov.region_off << ", at limit " << cov.lim_at << ", limit + 1 "
                         << cov.lim_above << ", at texture " << cov.tex_at << ", texture - 1 "
                         << cov.tex_below << ", at thresh " << cov.uniq_at << ", thresh + 1 "
                         << cov.uniq_above << ", near below " << cov.near_below << ", max m * 255 "
                         << cov.uniq_prod_max << ", fit " << cov.fit << ", frac 128 "
                         << cov.fit_q128 << ", frac < 0 rounding down " << cov.fit_down
                         << ", diff 0 " << cov.fit_flat << ", frac 16 k + 1 " << cov.fit_exact
                         << ", edge " << cov.edge << ", edge best last " << cov.edge_best_last
                         << ", edge garbage below " << cov.edge_garbage_below);
  for (const long c : {cov.ties,       cov.best_first,     cov.best_last,         cov.garbage_below,
                       cov.all_max,    cov.n_one,          cov.region_off,        cov.lim_at,
                       cov.lim_above,  cov.tex_at,         cov.tex_below,         cov.uniq_at,
                       cov.uniq_above, cov.near_below,     cov.uniq_prod_max,     cov.fit,
                       cov.fit_q128,   cov.fit_down,       cov.fit_flat,          cov.fit_exact,
                       cov.edge,       cov.edge_best_last, cov.edge_garbage_below})
    CHECK(c >= 20);
}

/// floor(m U / 100) == (m K) >> KShift with K = ceil(U 2^KShift / 100), the unit's ROM word,
/// for every m < 2^SadBits and every U <= 255, with the shift it chose at elaboration.
template <typename VMod, typename P>
void check_reciprocal() {
  constexpr std::uint64_t mmax = static_cast<std::uint64_t>(P::kMaxSad);
  constexpr unsigned shift = VMod::KShift;
  std::uint64_t wrong = 0;
  for (std::uint64_t u = 0; u <= 255; ++u) {
    const std::uint64_t k = ((u << shift) + 99) / 100;
    for (std::uint64_t m = 0; m <= mmax; ++m) wrong += (m * u / 100 != (m * k) >> shift);
  }
  INFO("KShift " << shift << ", m up to " << mmax);
  CHECK(wrong == 0);
}

}  // namespace

TEST_CASE("decide's reciprocal division by 100 is exact for every m and U", "[disparity][rtl]") {
  check_reciprocal<Vdecide_n8_scw_disparity_decide, N8>();
  check_reciprocal<Vdecide_n45_scw_disparity_decide, N45>();
}

TEST_CASE("scw_disparity_decide equals decide() every clock, 8 candidates", "[disparity][rtl]") {
  check_decide<Vdecide_n8, N8>("decide_n8", 1500, 8);
}

TEST_CASE("scw_disparity_decide equals decide() every clock, 45 candidates", "[disparity][rtl]") {
  check_decide<Vdecide_n45, N45>("decide_n45", 1200, 45);
}
