// SPDX-License-Identifier: Apache-2.0
// Ground-removal stage: compile-time parameters, run-time configuration and the validity rule
// (docs/ground.md).
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

#include "hls/common/beat.hpp"
#include "hls/common/line_buffer.hpp"

namespace scw::hls::ground {

/// One disparity in and out, Q11.4 two's complement in 16 bits, as the disparity stage emits it
/// and the labelling stage takes it. Invalid = 0 or negative (bit 15 set).
using disp_t = std::uint16_t;

/// The window: the current pixel and the 10 above it in its column (thesis 6.2: 11 x 1).
inline constexpr int kWindowRows = 11;
/// Clocks of the decision after the line buffer: the comparisons, then the AND and the zeroing
/// (rtl_models/ground/scw_ground.sv, DecideLatency).
inline constexpr int kDecideLatency = 2;
/// Largest Q11.4 value a configuration field takes (the RTL's 15-bit cfg ports).
inline constexpr int kMaxQ4 = 0x7fff;

/// Built-in capacity of one stage: rows up to MaxWidthPx pixels, one pixel per beat (the
/// single source the RTL's parameters are checked against).
template <int MaxWidthPx>
struct GroundParams {
  static constexpr int kMaxWidthPx = MaxWidthPx;
  static constexpr int kRows = kWindowRows;
  /// The 10 rows above, one 16-bit disparity per column and row.
  using line_params = LineBufferParams<1, MaxWidthPx, kRows>;
  /// Cycles from accepting a beat to presenting it without stalls: the line buffer's RAM read,
  /// the RAM's output register (scw_line_buffer with RdReg) and its output register, then the
  /// decision (scw_ground's Latency, checked at compile time).
  static constexpr int kLineLatency = line_params::kLatency + 1;
  static constexpr int kLatency = kLineLatency + kDecideLatency;
  using in_beat = Beat<disp_t, 1>;
  using out_beat = Beat<disp_t, 1>;
  static_assert(MaxWidthPx >= 2, "a row of at least 2 pixels");
};

/// Run-time configuration (the RTL's cfg_* ports), stable while frames stream. All Q11.4 (px x
/// 16), 0 .. 32767. The defaults are default_ground_config(0.54, 1.20) (host/reference/
/// ground_ref.hpp): the project's default rig, baseline 0.54 m, camera 1.20 m above the road.
/// No width or height: rows are as long as their eol says (up to MaxWidthPx), and the row count
/// restarts at every sof.
struct GroundConfig {
  bool enable = true;     // false: every disparity passes unchanged
  int step_tol_q4 = 4;    // each one-row step down may fall by at most this (0.25 px)
  int min_rise_q4 = 36;   // rise over the window (current - 10 rows up), inclusive bounds:
  int max_rise_q4 = 144;  //   0.5x and 2x the ground's 10 b / h px (4.5 px at the defaults)

  friend bool operator==(const GroundConfig& a, const GroundConfig& b) {
    return a.enable == b.enable && a.step_tol_q4 == b.step_tol_q4 &&
           a.min_rise_q4 == b.min_rise_q4 && a.max_rise_q4 == b.max_rise_q4;
  }
};

/// Throws std::invalid_argument naming the field outside 0 .. 32767 (what the ports carry).
inline void check_config([[maybe_unused]] const GroundConfig& cfg) {
#ifndef __SYNTHESIS__  // the host's check: a synthesised top trusts its registers
  auto check = [](int v, const char* name) {
    if (v < 0 || v > kMaxQ4)
      throw std::invalid_argument(std::string("ground: ") + name + " = " + std::to_string(v) +
                                  " outside 0 .. 32767 (Q11.4)");
  };
  check(cfg.step_tol_q4, "step_tol_q4");
  check(cfg.min_rise_q4, "min_rise_q4");
  check(cfg.max_rise_q4, "max_rise_q4");
#endif
}

/// A disparity the rule may call ground: nonzero and not negative as int16.
constexpr bool is_valid(disp_t d) { return d != 0 && d < 0x8000u; }

}  // namespace scw::hls::ground
