// SPDX-License-Identifier: Apache-2.0
// Road stage: compile-time parameters, run-time configuration and the fixed-point line and band
// arithmetic (docs/road.md).
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

#include "hls/common/beat.hpp"

namespace scw::hls::road {

/// One disparity in and out, Q11.4 two's complement in 16 bits, as the disparity stage emits it
/// and the labelling stage takes it. Invalid = 0 or negative (bit 15 set).
using disp_t = std::uint16_t;

/// Fraction bits of every line value: a road disparity d(v) = b + a v is held as code x 2^12
/// (Q11.4 code, 12 more bits), so a slope of 0.45 px a row is 29,491 and 480 rows of it add up
/// with an error under 1/8 code.
inline constexpr int kFracBits = 12;
/// One px of disparity in a line's units (code x 2^12), for the host's conversions.
inline constexpr double kPxUnit = 16.0 * (1 << kFracBits);
/// Slopes below 2^18 (4 px a row, about 9 times a car camera's road) and intercepts within
/// +-2^28 (a fitted one is at most a_max x h_max < 2^28): every band line and, with rows below
/// 1,024, every row value stays inside a signed 32-bit integer.
inline constexpr int kSlopeBits = 18;
inline constexpr std::int64_t kMaxSlope = (std::int64_t{1} << kSlopeBits) - 1;
inline constexpr std::int64_t kMaxIntercept = (std::int64_t{1} << 28) - 1;
/// Clocks the fit between two frames takes (the RTL's serial multiply and divide engine,
/// rtl_models/road/scw_road_fit.sv, needs 186 of them and starts 5 clocks in; checked at
/// elaboration): the next frame's sof waits this long, plus the clock that sees it.
inline constexpr int kFitClocks = 256;
/// Clocks from accepting a beat to presenting it: the compares, then the zeroing.
inline constexpr int kLatency = 2;

/// Built-in capacity: rows up to MaxWidthPx pixels in beats of P, frames up to MaxHeight rows.
/// Every sum of the fit stays below 2^63 (docs/road.md, "Widths").
template <int P, int MaxWidthPx, int MaxHeight>
struct RoadParams {
  static constexpr int kPpc = P;
  static constexpr int kMaxWidthPx = MaxWidthPx;
  static constexpr int kMaxHeight = MaxHeight;
  using in_beat = Beat<disp_t, P>;
  using out_beat = Beat<disp_t, P>;
  static_assert(MaxWidthPx >= 2 && MaxWidthPx <= 2048, "rows of 2 .. 2048 pixels");
  static_assert(MaxHeight >= 2 && MaxHeight <= 1024, "frames of 2 .. 1024 rows");
};

/// A line over rows, d(v) = b + a v, in code x 2^12 (Q.12 of a Q11.4 code).
struct Line {
  std::int32_t a = 0;  // per row, 0 .. 2^18 - 1
  std::int32_t b = 0;  // at row 0, signed
  friend bool operator==(const Line& x, const Line& y) { return x.a == y.a && x.b == y.b; }
  friend bool operator!=(const Line& x, const Line& y) { return !(x == y); }
};

/// Run-time configuration (the RTL's cfg_* ports), stable while frames stream.
/// host/road/setup.hpp fills it from the rig (metres, pixels) and documents the defaults.
struct RoadConfig {
  bool enable = true;        // false: every disparity passes unchanged (the road is still fitted)
  Line nominal{};            // the road until a frame gives a plausible one (flat road, nominal
                             //   camera height: a = 16 x 2^12 x b / H, b = -a cv)
  std::int32_t a_min = 0;    // a fitted slope is plausible within a_min .. a_max (camera height
  std::int32_t a_max = 0;    //   twice to half the nominal)
  std::uint16_t h_min = 0;   // and its horizon row -b / a within h_min .. h_max (the pitch)
  std::uint16_t h_max = 0;
  std::uint16_t tol_q4 = 16;     // road pixel: |d - d_road| <= tol + tol_rel d_road, Q11.4
  std::uint8_t tol_rel_q8 = 38;  //   Q0.8 (38 / 256 = 0.148)
  std::uint16_t gate_q4 = 64;    // a pixel takes part in the next fit within gate + gate_rel
  std::uint8_t gate_rel_q8 = 38; //   d_road of this frame's road
  std::uint32_t min_count = 2000;  // a fit needs this many pixels in the gate (20 bits)

  friend bool operator==(const RoadConfig& x, const RoadConfig& y) {
    return x.enable == y.enable && x.nominal == y.nominal && x.a_min == y.a_min &&
           x.a_max == y.a_max && x.h_min == y.h_min && x.h_max == y.h_max &&
           x.tol_q4 == y.tol_q4 && x.tol_rel_q8 == y.tol_rel_q8 && x.gate_q4 == y.gate_q4 &&
           x.gate_rel_q8 == y.gate_rel_q8 && x.min_count == y.min_count;
  }
};

/// Throws std::invalid_argument naming the field outside what the ports carry.
inline void check_config([[maybe_unused]] const RoadConfig& c) {
#ifndef __SYNTHESIS__  // the host's check: a synthesised top trusts its registers
  auto fail = [](const std::string& what) { throw std::invalid_argument("road: " + what); };
  auto slope = [&](std::int64_t v, const char* name) {
    if (v < 0 || v > kMaxSlope)
      fail(std::string(name) + " = " + std::to_string(v) + " outside 0 .. 262143 (code x 2^12 a "
           "row: 0 .. 4 px a row)");
  };
  slope(c.nominal.a, "nominal slope");
  slope(c.a_min, "a_min");
  slope(c.a_max, "a_max");
  if (c.nominal.b < -kMaxIntercept || c.nominal.b > kMaxIntercept)
    fail("nominal intercept = " + std::to_string(c.nominal.b) + " outside +-2^28 (a horizon "
         "within 1,023 rows of the steepest road)");
  if (c.a_min > c.a_max)
    fail("a_min = " + std::to_string(c.a_min) + " above a_max = " + std::to_string(c.a_max));
  if (c.h_min > c.h_max || c.h_max > 1023)
    fail("horizon rows " + std::to_string(c.h_min) + " .. " + std::to_string(c.h_max) +
         ": need h_min <= h_max <= 1023");
  if (c.tol_q4 > 0x7fff || c.gate_q4 > 0x7fff)
    fail("tol_q4 / gate_q4 above 32767 (Q11.4)");
  if (c.min_count < 1 || c.min_count >= (1u << 20))
    fail("min_count = " + std::to_string(c.min_count) + " outside 1 .. 2^20 - 1");
#endif
}

/// A disparity the stage may call road: nonzero and not negative as int16.
constexpr bool is_valid(disp_t d) { return d != 0 && d < 0x8000u; }

/// The band `line` +- (tol + tol_rel line) as two lines (low, high): lo = b - (b r >> 8) - t 2^12
/// and a - (a r >> 8), the shifts arithmetic (floor), as the RTL's fit engine forms them.
struct Band {
  Line lo, hi;
};
constexpr Band band(const Line& l, std::uint16_t tol_q4, std::uint8_t rel_q8) {
  const std::int64_t ra = (std::int64_t{l.a} * rel_q8) >> 8;
  const std::int64_t rb = (std::int64_t{l.b} * rel_q8) >> 8;
  const std::int64_t t = std::int64_t{tol_q4} << kFracBits;
  Band out;
  out.lo.a = static_cast<std::int32_t>(l.a - ra);
  out.lo.b = static_cast<std::int32_t>(l.b - rb - t);
  out.hi.a = static_cast<std::int32_t>(l.a + ra);
  out.hi.b = static_cast<std::int32_t>(l.b + rb + t);
  return out;
}

/// The least-squares sums over one frame's pixels in the gate: count, rows, rows squared,
/// codes, rows x codes.
struct FitSums {
  std::uint64_t n = 0, sv = 0, svv = 0, sd = 0, svd = 0;
};

/// The fit the engine computes between frames, exactly (docs/road.md, "The fit"): the line
/// through the gate's pixels, or `keep` when it is not a plausible road.
///   den = n svv - sv^2, num = n svd - sv sd; a = floor(num 2^12 / den);
///   c = a sv - sd 2^12; b = -floor(c / n).
/// Plausible: n >= min_count, den > 0, num > 0, a_min <= a <= a_max, c >= 0 (horizon at or
/// below row 0), h_min a <= -b <= h_max a.
inline Line fit_line(const FitSums& s, const RoadConfig& cfg, const Line& keep) {
  __extension__ typedef __int128 i128;  // products up to 2^64 and a shift of 12
  if (s.n < cfg.min_count) return keep;
  const i128 den = i128(s.n) * s.svv - i128(s.sv) * s.sv;
  const i128 num = i128(s.n) * s.svd - i128(s.sv) * s.sd;
  if (den <= 0 || num <= 0) return keep;
  if (num >= (den << (kSlopeBits - kFracBits))) return keep;  // a >= 2^18
  const i128 a = (num << kFracBits) / den;
  if (a < cfg.a_min || a > cfg.a_max) return keep;
  const i128 c = a * i128(s.sv) - (i128(s.sd) << kFracBits);
  if (c < 0) return keep;
  const i128 nb = c / i128(s.n);  // -b
  if (nb < a * cfg.h_min || nb > a * cfg.h_max) return keep;
  return Line{static_cast<std::int32_t>(a), static_cast<std::int32_t>(-nb)};
}

}  // namespace scw::hls::road
