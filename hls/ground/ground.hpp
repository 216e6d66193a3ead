// SPDX-License-Identifier: Apache-2.0
// Ground-removal kernel: a disparity leaves as 0 when its causal 11 x 1 column window is a ramp.
#pragma once

#include <cstdint>

#include "hls/common/line_buffer.hpp"
#include "hls/common/stream.hpp"
#include "hls/ground/ground_params.hpp"

namespace scw::hls::ground {

/// The stage, the twin of rtl_models/ground/scw_ground.sv. `step()` is the body of an II=1
/// loop over beats: it takes one disparity and returns it, or 0 when it is ground
/// (docs/ground.md):
///   the window is the pixel and the 10 above it in its column, g[0] (10 rows up) .. g[10]
///   (the pixel); the pixel is ground when cfg.enable, all 11 are valid (is_valid), every step
///   g[j+1] - g[j] >= -step_tol and min_rise <= g[10] - g[0] <= max_rise.
/// Rows 0 .. 9 of a frame see 0 (invalid) above the top and pass unchanged. Geometry and errors
/// are the line buffer's: rows as long as their eol says up to MaxWidthPx (a longer row's extra
/// beats pass unchanged), a row too long or a sof before eol sets the sticky error(), and the
/// next sof resynchronises.
///
/// The RTL computes the window (the line buffer, 3 clocks) and the decision (2 clocks) in two
/// pipelines with an enable each; `window()` and `decide()` are those two halves, so
/// sim::GroundModel can clock them as the RTL does.
template <typename Params>
class Ground {
 public:
  using params = Params;
  static constexpr int kRows = Params::kRows;
  using in_type = typename Params::in_beat;
  using out_type = typename Params::out_beat;
  using line_buffer_type = LineBuffer<disp_t, typename Params::line_params>;
  /// rows[k][0]: the pixel k rows above the current one (rows[0] the current pixel).
  using column_type = typename line_buffer_type::out_type;

  explicit Ground(const GroundConfig& cfg) : cfg_(cfg) { check_config(cfg); }

  /// One beat: the whole stage (the frame loop's body).
  out_type step(const in_type& in) {
    // clang-format off
#pragma HLS INLINE
    // clang-format on
    return decide(window(in));
  }

  /// First half: the beat with the 10 rows above (0 above the frame top); advances the line
  /// buffer.
  column_type window(const in_type& in) { return lb_.step(in); }

  /// Second half: the beat out. Valid disparities are 1 .. 0x7fff, so on them every sum below is
  /// exact in 16 bits; on a window with an invalid value the comparisons do not matter.
  out_type decide(const column_type& c) const {
    // clang-format off
#pragma HLS INLINE
    // clang-format on
    bool all_valid = true;
    for (int k = 0; k < kRows; ++k) {
      // clang-format off
#pragma HLS UNROLL
      // clang-format on
      all_valid = all_valid && is_valid(c.rows[k][0]);
    }
    auto v15 = [](disp_t d) { return static_cast<std::uint16_t>(d & 0x7fffu); };  // Q11.4 >= 0
    const std::uint16_t tol = static_cast<std::uint16_t>(cfg_.step_tol_q4);
    bool steps_ok = true;
    // Row k+1 to row k is one step down: r_k - r_{k+1} >= -tol, i.e. r_k + tol >= r_{k+1}.
    for (int k = 0; k + 1 < kRows; ++k) {
      // clang-format off
#pragma HLS UNROLL
      // clang-format on
      steps_ok = steps_ok && v15(c.rows[k][0]) + tol >= v15(c.rows[k + 1][0]);
    }
    const std::uint16_t cur = v15(c.rows[0][0]), top = v15(c.rows[kRows - 1][0]);
    const bool rise_ok = cur >= top + cfg_.min_rise_q4 && cur <= top + cfg_.max_rise_q4;
    out_type out;
    out.px[0] = cfg_.enable && all_valid && steps_ok && rise_ok ? disp_t{0} : c.rows[0][0];
    out.sof = c.sof;
    out.eol = c.eol;
    return out;
  }

  /// Sticky: a row longer than MaxWidthPx or a sof before the previous row's eol was seen.
  bool error() const { return lb_.error(); }
  const GroundConfig& config() const { return cfg_; }

 private:
  GroundConfig cfg_;
  line_buffer_type lb_{};
};

// The loop label names the loop in HLS reports; g++ would call it unused.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-label"
/// A frame (or several) of beats through the stage with no stalls: one output beat per input
/// beat, in order. What an HLS tool synthesises as the stage's top; `n` beats from `in` to `out`,
/// hls::stream (or ArrayIn / ArrayOut).
template <typename Params, typename In, typename Out, if_port<Out> = 0>
void ground_frame(Ground<Params>& g, In& in, Out& out, int n) {
  // clang-format off
#pragma HLS INTERFACE axis port=in
#pragma HLS INTERFACE axis port=out
#pragma HLS INTERFACE s_axilite port=n
#pragma HLS INTERFACE s_axilite port=return
  // clang-format on
loop_beat:
  for (int i = 0; i < n; ++i) {
    // clang-format off
#pragma HLS PIPELINE II=1
    // clang-format on
    out.write(g.step(in.read()));
  }
}
#pragma GCC diagnostic pop

/// The frame function over arrays (tests).
template <typename Params>
void ground_frame(Ground<Params>& g, const typename Params::in_beat* in,
                  typename Params::out_beat* out, int n) {
  ArrayIn<typename Params::in_beat> i(in, n);
  ArrayOut<typename Params::out_beat> o(out);
  ground_frame(g, i, o, n);
}

}  // namespace scw::hls::ground
