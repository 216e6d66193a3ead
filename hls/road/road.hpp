// SPDX-License-Identifier: Apache-2.0
// Road kernel: a v-disparity road fitted from the previous frame; this frame's pixels on it leave
// as 0.
#pragma once

#include <cstdint>

#include "hls/common/stream.hpp"
#include "hls/road/road_params.hpp"

namespace scw::hls::road {

/// The stage, the twin of rtl_models/road/scw_road.sv (docs/road.md). Per beat (`step()`, the
/// body of an II=1 loop) each pixel of row v is compared with two bands about the road of the
/// previous frame, d_road(v) = b + a v:
///   - road: within tol + tol_rel d_road of it; leaves as 0 (when cfg.enable);
///   - gate: within gate + gate_rel d_road; adds (v, d) to the least-squares sums of this frame.
/// Rows where d_road < 1 px (at and above the horizon) have neither. Between frames (`fit()`, at
/// the next sof) the sums give the next frame's road (fit_line), and the bands are formed again.
/// The row values are registers stepped by the bands' slopes at every eol, so no pixel needs a
/// multiply; rows past MaxHeight - 1 keep the last row's values.
template <typename Params>
class Road {
 public:
  using params = Params;
  static constexpr int P = Params::kPpc;
  using in_type = typename Params::in_beat;
  using out_type = typename Params::out_beat;

  explicit Road(const RoadConfig& cfg) : cfg_(cfg), line_(cfg.nominal) { check_config(cfg); }

  /// Whether this beat must wait for the fit: a sof after a frame's beats (or the first sof after
  /// reset, which forms the nominal road's bands).
  bool needs_fit(const in_type& in) const { return in.sof && seen_; }

  /// The fit between frames: the next road from this frame's sums, its bands, the sums cleared.
  void fit() {
    line_ = fit_line(sums_, cfg_, line_);
    road_band_ = band(line_, cfg_.tol_q4, cfg_.tol_rel_q8);
    gate_band_ = band(line_, cfg_.gate_q4, cfg_.gate_rel_q8);
    sums_ = FitSums{};
    seen_ = false;
  }

  /// One beat (the frame loop's body; call fit() first when needs_fit()).
  out_type step(const in_type& in) {
    // clang-format off
#pragma HLS INLINE
    // clang-format on
    if (in.sof) {
      v_ = 0;
      row_ = Rows{line_.b, road_band_.lo.b, road_band_.hi.b, gate_band_.lo.b, gate_band_.hi.b};
    }
    const bool active = row_.road >= (std::int64_t{16} << kFracBits);  // d_road >= 1 px
    out_type out;
    for (int i = 0; i < P; ++i) {
      // clang-format off
#pragma HLS UNROLL
      // clang-format on
      const disp_t d = in.px[i];
      const std::int64_t x = std::int64_t{d} << kFracBits;
      const bool ok = active && is_valid(d);
      const bool on_road = ok && x >= row_.lo && x <= row_.hi;
      if (ok && x >= row_.glo && x <= row_.ghi) {
        sums_.n += 1;
        sums_.sv += static_cast<std::uint64_t>(v_);
        sums_.svv += static_cast<std::uint64_t>(v_) * v_;
        sums_.sd += d;
        sums_.svd += static_cast<std::uint64_t>(v_) * d;
      }
      out.px[i] = cfg_.enable && on_road ? disp_t{0} : d;
    }
    out.sof = in.sof;
    out.eol = in.eol;
    seen_ = true;
    if (in.eol && v_ < Params::kMaxHeight - 1) {
      ++v_;
      row_.road += line_.a;
      row_.lo += road_band_.lo.a;
      row_.hi += road_band_.hi.a;
      row_.glo += gate_band_.lo.a;
      row_.ghi += gate_band_.hi.a;
    }
    return out;
  }

  const Line& line() const { return line_; }
  const FitSums& sums() const { return sums_; }
  const RoadConfig& config() const { return cfg_; }

 private:
  struct Rows {  // the current row's values, code x 2^12
    std::int64_t road = 0, lo = 0, hi = 0, glo = 0, ghi = 0;
  };
  RoadConfig cfg_;
  Line line_;
  Band road_band_{}, gate_band_{};
  FitSums sums_{};
  Rows row_{};  // 0 until the first sof: no row is active before it
  int v_ = 0;
  bool seen_ = true;  // after reset the first sof forms the nominal road's bands
};

// The loop label names the loop in HLS reports; g++ would call it unused.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-label"
/// Beats through the stage with no stalls, the fit run at every sof that needs it: one output
/// beat per input beat, in order, and at each sof the line that frame is gated with to `lines`
/// (the warning stage's road input). What an HLS tool synthesises as the stage's top (the fit as
/// a separate, non-pipelined region); `n` beats from `in` to `out`. The ports are hls::stream (or
/// ArrayIn / ArrayOut / Discard).
template <typename Params, typename In, typename Out, typename Lines, if_port<Out> = 0>
void road_frame(Road<Params>& r, In& in, Out& out, Lines& lines, int n) {
  // clang-format off
#pragma HLS INTERFACE axis port=in
#pragma HLS INTERFACE axis port=out
#pragma HLS INTERFACE axis port=lines
#pragma HLS INTERFACE s_axilite port=n
#pragma HLS INTERFACE s_axilite port=return
  // clang-format on
loop_beat:
  for (int i = 0; i < n; ++i) {
    // clang-format off
#pragma HLS PIPELINE II=1
    // clang-format on
    const typename Params::in_beat b = in.read();
    if (r.needs_fit(b)) r.fit();
    if (b.sof) lines.write(r.line());  // after the fit, as the RTL's line register samples it
    out.write(r.step(b));
  }
}
#pragma GCC diagnostic pop

/// The frame function over arrays, the lines dropped (tests, vector sets).
template <typename Params>
void road_frame(Road<Params>& r, const typename Params::in_beat* in,
                typename Params::out_beat* out, int n) {
  ArrayIn<typename Params::in_beat> i(in, n);
  ArrayOut<typename Params::out_beat> o(out);
  Discard lines;
  road_frame(r, i, o, lines, n);
}

}  // namespace scw::hls::road
