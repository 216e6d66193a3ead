// SPDX-License-Identifier: Apache-2.0
// Disparity kernel: SAD block matching with incremental column sums, all candidates per beat.
#pragma once

#include <array>
#include <cstdint>

#include "hls/common/beat.hpp"
#include "hls/common/force_inline.hpp"
#include "hls/common/stream.hpp"
#include "hls/disparity/decide_latency.hpp"
#include "hls/disparity/disparity_params.hpp"
#include "hls/disparity/prefilter.hpp"

namespace scw::hls::disparity {

/// SAD of one candidate over the window: at most N * N * 255 (Q17.0 at N = 21).
using sad_t = std::uint32_t;

/// The winner of one pixel's candidates, the rejection rules and the value (docs/disparity.md),
/// a pure function of the N x N SADs of the NumDisp candidates and the window's texture sum;
/// used by the streaming kernel, not by the direct reference (host/reference/disparity_ref.hpp).
/// `limit`: the candidates whose window lies inside the right image (edge_limit; all of them
/// but at the left edge); only the first min(candidates, limit) take part.
template <int NumDisp>
disp_t decide(const std::array<sad_t, NumDisp>& sad, sad_t texture, const DisparityConfig& cfg,
              int limit = NumDisp) {
  const int built = candidates<NumDisp>(cfg);  // the first n of the built candidates
  const int n = limit < built ? limit : built;
  // The smallest SAD, then the largest d that has it (ties go to the larger d, as in
  // cv::StereoBM); two passes, each a reduction a compiler vectorises. A SAD is at most
  // N * N * 255 (and the uniqueness threshold 3.55 times that), far below 2^31: compared as
  // signed, which baseline x86-64 vectorises (SSE2 has no unsigned 32-bit compare).
  std::int32_t least = static_cast<std::int32_t>(sad[0]);
  for (int d = 1; d < n; ++d) {
    const auto v = static_cast<std::int32_t>(sad[d]);
    least = v < least ? v : least;
  }
  const sad_t m = static_cast<sad_t>(least);
  int best = n > 1 ? n - 1 : 0;
  while (sad[best] != m) --best;
  if (cfg.sad_limit > 0 && m > static_cast<sad_t>(cfg.sad_limit)) return invalid_code(cfg);
  if (cfg.texture_threshold > 0 && texture < static_cast<sad_t>(cfg.texture_threshold))
    return invalid_code(cfg);
  if (cfg.uniqueness_ratio > 0) {
    // Rejected when a candidate other than the winner and its two neighbours is within the
    // ratio: count all within it, then take the three out.
    const sad_t thresh = m + m * static_cast<sad_t>(cfg.uniqueness_ratio) / 100;
    int close = 0;
    const auto within = static_cast<std::int32_t>(thresh);
    for (int d = 0; d < n; ++d) close += static_cast<std::int32_t>(sad[d]) <= within ? 1 : 0;
    for (int d = best > 0 ? best - 1 : 0; d <= best + 1 && d < n; ++d)
      close -= sad[d] <= thresh ? 1 : 0;
    if (close > 0) return invalid_code(cfg);
  }
  const int d = cfg.dmin + best;
  if (!cfg.subpixel || best == 0 || best == n - 1) return static_cast<disp_t>(d * 16);
  // StereoBM's fit: den >= 0, |frac| <= 128; floor division by 16 via an arithmetic shift.
  const int prev = static_cast<int>(sad[best - 1]), next = static_cast<int>(sad[best + 1]);
  const int diff = prev - next;
  const int den = prev + next - 2 * static_cast<int>(m) + (diff < 0 ? -diff : diff);
  const int frac = den != 0 ? diff * 256 / den : 0;
  return static_cast<disp_t>(static_cast<std::int16_t>((d * 256 + frac + 15) >> 4));
}

/// The streaming kernel: one pair of beats (left, right; P pixels of the same row) per call.
///
/// Frame-relative row y and column x of the newest pixel. N + 1 rows of each image are kept
/// (the row leaving the window, y - N, is read while row y is written); per candidate d and
/// column x the column sum C_d(x) = sum over rows y - N + 1 .. y of |L(x) - R(x - dmin - d)| is
/// updated by adding the new row's difference and subtracting the leaving row's; the window
/// sum for centre column x - r is the running S_d += C_d(x) - C_d(x - N). So each beat does
/// 2 P NumDisp absolute differences and 2 P NumDisp additions, whatever N is.
///
/// The result for output pixel (u, v) = (x - r, y - r) is pushed into `results` when v is in
/// the valid rows r .. H - r - 1 and u < W - r; every other output pixel is the invalid code,
/// which the reader (sim::DisparityModel, and the RTL) emits without waiting for input.
template <typename Params>
class DisparityCore {
 public:
  static constexpr int P = Params::kPpc;
  static constexpr int N = Params::kWindow;
  static constexpr int R = Params::kRadius;
  static constexpr int ND = Params::kNumDisp;
  static constexpr int W = Params::kMaxWidthPx;
  using pixel_beat = typename Params::pixel_beat;

  explicit DisparityCore(const DisparityConfig& cfg = {})
      : cfg_(cfg), nd_(candidates<ND>(cfg)), edge_min_(edge_min<ND>(cfg)) {}
  const DisparityConfig& config() const { return cfg_; }

  /// Processes the beat at (x0, y); calls `emit(disp_t)` once per result pixel, in raster
  /// order of the output pixels they belong to.
  template <typename Emit>
  void step(int x0, int y, const pixel_beat& l, const pixel_beat& r, Emit&& emit) {
    // clang-format off
#pragma HLS INLINE
    // clang-format on
    const int slot = y % (N + 1);
    const int old_slot = (y + 1) % (N + 1);  // row y - N
    for (int i = 0; i < P; ++i) {
      left_[slot][x0 + i] = l.px[i];
      right_[slot][x0 + i] = r.px[i];
    }
    for (int i = 0; i < P; ++i) {
      const int x = x0 + i;
      // Candidates are kept in reverse order, k = nd_ - 1 - d, so that the right pixel candidate
      // k reads, x - dmin - d = base + k, rises with k: every loop below is a forward straight
      // line over k that a compiler vectorises (a reversed byte load is not, on baseline x86-64).
      // The hardware holds each candidate's sums in registers of its own; the order is the
      // model's. Candidates whose right pixel lies left of the image (k < first) sum to 0.
      int inside = x - cfg_.dmin + 1;
      inside = inside < 0 ? 0 : (inside > nd_ ? nd_ : inside);
      const int first = nd_ - inside;
      const int base = x - cfg_.dmin - nd_ + 1;
      // __restrict: the 8-bit pixels could otherwise alias the sums (a char type aliases
      // anything), and the loops would stay scalar.
      std::uint16_t* __restrict col = col_[x].data();
      const std::uint16_t* __restrict leaving = x >= N ? col_[x - N].data() : zeros_.data();
      const int l_new = left_[slot][x], l_old = left_[old_slot][x];
      const pixel_t* __restrict r_new = right_[slot].data();
      const pixel_t* __restrict r_old = right_[old_slot].data();
      for (int k = 0; k < first; ++k) col[k] = 0;
      if (y == 0) {
        for (int k = first; k < nd_; ++k)
          col[k] = static_cast<std::uint16_t>(absdiff(l_new, r_new[base + k]));
      } else if (y >= N) {
        for (int k = first; k < nd_; ++k)
          col[k] = static_cast<std::uint16_t>(col[k] + absdiff(l_new, r_new[base + k]) -
                                              absdiff(l_old, r_old[base + k]));
      } else {
        for (int k = first; k < nd_; ++k)
          col[k] = static_cast<std::uint16_t>(col[k] + absdiff(l_new, r_new[base + k]));
      }
      if (x == 0) win_.fill(0);
      for (int k = 0; k < nd_; ++k) win_[k] += static_cast<sad_t>(col[k]) - leaving[k];
      // Texture: the same column and window sums of |L - cap| (StereoBM's texture measure).
      int t = absdiff(left_[slot][x], cfg_.prefilter_cap);
      if (y > 0) t += tcol_[x];
      if (y >= N) t -= absdiff(left_[old_slot][x], cfg_.prefilter_cap);
      tcol_[x] = static_cast<std::uint16_t>(t);
      twin_ = (x == 0 ? 0 : twin_) + static_cast<sad_t>(t) - (x >= N ? tcol_[x - N] : 0);
      const int u = x - R, v = y - R;
      if (u < 0 || v < R) continue;
      // All nd_ candidates inside the right image, or at least edge_min_ of them (the left edge).
      const int limit = edge_limit<ND>(cfg_, u, R);
      if (limit < edge_min_) {
        emit(invalid_code(cfg_));
        continue;
      }
      for (int d = 0; d < nd_; ++d) sad_[d] = win_[nd_ - 1 - d];  // back to candidate order
      emit(decide<ND>(sad_, twin_, cfg_, limit));
    }
  }

 private:
  static int absdiff(int a, int b) { return a > b ? a - b : b - a; }

  DisparityConfig cfg_;
  int nd_;        // candidates in use, candidates<ND>(cfg_)
  int edge_min_;  // the fewest a pixel is decided among, edge_min<ND>(cfg_)
  std::array<std::array<pixel_t, W>, N + 1> left_{};
  std::array<std::array<pixel_t, W>, N + 1> right_{};
  // Column sums Q16.0 (at most N * 255), by column then candidate (k = nd_ - 1 - d): a pixel's
  // candidates are adjacent in memory.
  std::array<std::array<std::uint16_t, ND>, W> col_{};
  static constexpr std::array<std::uint16_t, ND> zeros_{};  // the leaving column left of x = N
  std::array<sad_t, ND> win_{};                             // window sums, by k
  std::array<sad_t, ND> sad_{};                             // the same, by d, for decide()
  std::array<std::uint16_t, W> tcol_{};  // texture column sums, at most N * 255
  sad_t twin_ = 0;
};

/// The stage around the core, the body of an II=1 loop (one clock() per clock cycle), twin of
/// the RTL's control: a writer takes one left and one right beat together and feeds the core;
/// results wait in a small queue; a reader emits the output frame in raster order, results
/// where the core computes them and the invalid code everywhere else (the top and bottom R
/// rows, the last R columns), so that the bottom rows of a frame leave while the next frame's
/// first rows come in: one beat per clock in steady state, no flush. With cfg.prefilter both
/// images pass an XSobel kernel first (two rows later, still one beat per clock).
///
/// Timing is the RTL's (rtl_models/disparity/scw_disparity.sv): the core is a free-running
/// pipeline, so the results of a beat fed to it at clock t can be read from clock t + kLatency
/// on; the queue counts them as soon as the beat is fed (credits), so it never overflows and
/// never stalls the pipeline, and kQueue covers the pipeline so the stage still takes one beat
/// per clock.
///
/// Geometry comes from the configuration; sof/eol are checked, never trusted (sticky error()).
/// A sof in the middle of a frame is held while the writer feeds the rest of the interrupted
/// frame as zero pixels, one beat per clock, so the output stays whole frames and the next
/// frame is exact; a beat that should start a frame but has no sof is dropped.
template <typename Params>
class Disparity {
 public:
  static constexpr int P = Params::kPpc;
  static constexpr int R = Params::kRadius;
  /// Clocks from feeding a beat to the core to reading its results: the prefilter's read (the
  /// raw path is delayed as much, so both modes share one latency), front_latency to the window
  /// sums, the decision unit, and the queue's write.
  static constexpr int kLatency = XSobel<Params>::kReadLatency + front_latency(P) +
                                  decide_latency(Params::kNumDisp) + 1;
  /// Result queue in pixels, a power of two per lane: room for the pipeline's kLatency beats,
  /// the beat being fed and the one being read (docs/disparity.md).
  static constexpr int kQueue = P * queue_words(kLatency + 2);
  using params = Params;
  using in_type = typename Params::pixel_beat;
  using out_type = typename Params::disp_beat;

  struct Emit {
    bool valid = false;
    out_type beat{};
  };

  explicit Disparity(const DisparityConfig& cfg = {}) : cfg_(cfg), core_(cfg) {
    xs_l_.configure(cfg.width, cfg.height, cfg.prefilter_cap);
    xs_r_.configure(cfg.width, cfg.height, cfg.prefilter_cap);
  }
  const DisparityConfig& config() const { return cfg_; }
  bool error() const { return error_; }

  /// Both inputs are taken together, only when both are valid.
  bool in_ready(bool l_valid, bool r_valid) const {
    return !skip_ && !held_ && l_valid && r_valid && input_room();
  }
  /// Whether the reader can emit its next beat (given that the output advances).
  bool read_allowed() const {
    if (out_x_ == 0 && out_y_ == 0 && frames_in_ == frames_out_) return false;  // not started
    return ready_ >= computed_lanes();
  }

  /// One clock edge: `take` = a beat pair was accepted; `advance` = the output moves.
  /// Readers act before writers (read-first, as block RAM).
  Emit clock(bool take, const in_type& l, const in_type& r, bool advance) {
    // clang-format off
#pragma HLS INLINE
    // clang-format on
    Emit e;
    // Results that left the pipeline at the last edge; their slot becomes the newest, for the
    // results fed this clock (a ring of kLatency counters, the delay line's shift without
    // moving them).
    ready_ += arriving_[arrive_head_];
    arriving_[arrive_head_] = 0;
    arrive_new_ = arrive_head_;
    arrive_head_ = arrive_head_ + 1 == kLatency ? 0 : arrive_head_ + 1;
    // Every decision of this clock sees the state before its edge, as registers do.
    const bool room = input_room();
    const bool feed_prefiltered = cfg_.prefilter && xs_l_.read_allowed() && core_room();
    if (advance && read_allowed()) e = read_beat();
    // The raw pair entering this clock, if any: taken, a zero pair of an interrupted frame,
    // or the held first pair of the next frame.
    bool have = false;
    in_type bl{}, br{};
    if (take) {
      if (l.sof != r.sof || l.eol != r.eol) error_ = true;
      const bool frame_start = in_x_ == 0 && in_y_ == 0;
      if (l.sof && !frame_start) {
        error_ = true;
        held_ = true;
        held_l_ = l;
        held_r_ = r;
        skip_ = true;
      } else if (!l.sof && frame_start) {
        error_ = true;  // dropped: a frame starts with sof
      } else {
        if (l.eol != (in_x_ == cols() - 1)) error_ = true;
        have = true;
        bl = l;
        br = r;
      }
    } else if (skip_ && room) {
      have = true;  // the rest of an interrupted frame, as zeros
    } else if (held_ && room) {
      held_ = false;
      have = true;
      bl = held_l_;
      br = held_r_;
    }
    if (have) advance_input();
    if (!cfg_.prefilter) {
      if (have) write_core(bl, br);
      return e;
    }
    if (feed_prefiltered) {
      const in_type pl = xs_l_.read();
      write_core(pl, xs_r_.read());
    }
    if (have) {
      xs_l_.write(bl);
      xs_r_.write(br);
    }
    return e;
  }

 private:
  int cols() const { return cfg_.width / P; }
  bool core_room() const { return kQueue - count_ >= P; }
  bool input_room() const { return cfg_.prefilter ? xs_l_.write_allowed() : core_room(); }

  /// Counts the raw frame position (for the sof/eol checks and the resynchronisation).
  SCW_INLINE void advance_input() {
    if (++in_x_ < cols()) return;
    in_x_ = 0;
    if (++in_y_ == cfg_.height) {
      in_y_ = 0;
      skip_ = false;
    }
  }

  /// Feeds the core the next beat pair of its own frame raster (raw or prefiltered).
  SCW_INLINE void write_core(const in_type& l, const in_type& r) {
    if (core_x_ == 0 && core_y_ == 0) ++frames_in_;
    core_.step(core_x_ * P, core_y_, l, r, [this](disp_t v) {
      queue_[(head_ + count_) % kQueue] = v;
      ++count_;
      ++arriving_[arrive_new_];
    });
    if (++core_x_ < cols()) return;
    core_x_ = 0;
    if (++core_y_ == cfg_.height) core_y_ = 0;
  }

  bool computed(int u, int v) const {
    return v >= R && v < cfg_.height - R && u < cfg_.width - R;
  }
  SCW_INLINE int computed_lanes() const {
    int n = 0;
    for (int i = 0; i < P; ++i) n += computed(out_x_ * P + i, out_y_) ? 1 : 0;
    return n;
  }

  SCW_INLINE Emit read_beat() {
    Emit e;
    e.valid = true;
    const bool frame_start = out_x_ == 0 && out_y_ == 0;
    if (frame_start) ++frames_out_;
    for (int i = 0; i < P; ++i) {
      if (computed(out_x_ * P + i, out_y_)) {
        e.beat.px[i] = queue_[head_];
        head_ = (head_ + 1) % kQueue;
        --count_;
        --ready_;
      } else {
        e.beat.px[i] = invalid_code(cfg_);
      }
    }
    e.beat.sof = frame_start;
    e.beat.eol = out_x_ == cols() - 1;
    if (!e.beat.eol) {
      ++out_x_;
    } else {
      out_x_ = 0;
      if (++out_y_ == cfg_.height) out_y_ = 0;
    }
    return e;
  }

  DisparityConfig cfg_;
  DisparityCore<Params> core_;
  std::array<disp_t, kQueue> queue_{};
  int head_ = 0;
  int count_ = 0;  // results fed to the core and not yet read (the credits in use)
  int ready_ = 0;  // of those, the ones out of the pipeline
  // [(arrive_head_ + i) % kLatency]: results readable i + 1 clocks from now.
  std::array<int, kLatency> arriving_{};
  int arrive_head_ = 0, arrive_new_ = kLatency - 1;
  XSobel<Params> xs_l_, xs_r_;
  int in_x_ = 0, in_y_ = 0, core_x_ = 0, core_y_ = 0, out_x_ = 0, out_y_ = 0;
  unsigned frames_in_ = 0, frames_out_ = 0;
  bool skip_ = false, held_ = false, error_ = false;
  in_type held_l_{}, held_r_{};
};

// The loop label names the loop in HLS reports; g++ would call it unused.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-label"
/// Whole frames of beat pairs through the stage with no output stalls: `n` beats from `l` and `r`
/// (frames of the configured size, back to back), `n` disparity beats to `out`; returns how many
/// were written (n, unless the input breaks the frame geometry and `max_clocks` runs out first).
/// The loop is one clock of the stage an iteration: it takes the next pair when both have one and
/// the stage is ready (always, for well-formed frames with the output never stalled) and writes a
/// beat when one leaves. What an HLS tool synthesises as the stage's top: the ports are
/// hls::stream (or ArrayIn / ArrayOut).
template <typename Params, typename In, typename Out, if_port<Out> = 0>
int disparity_frame(Disparity<Params>& d, In& l, In& r, Out& out, int n, long max_clocks) {
  // clang-format off
#pragma HLS INTERFACE axis port=l
#pragma HLS INTERFACE axis port=r
#pragma HLS INTERFACE axis port=out
#pragma HLS INTERFACE s_axilite port=n
#pragma HLS INTERFACE s_axilite port=max_clocks
#pragma HLS INTERFACE s_axilite port=return
  // clang-format on
  using beat = typename Params::pixel_beat;
  int written = 0;
loop_clock:
  for (long c = 0; c < max_clocks && written < n; ++c) {
    // clang-format off
#pragma HLS PIPELINE II=1
    // clang-format on
    const bool take = !l.empty() && !r.empty() && d.in_ready(true, true);
    const beat lb = take ? l.read() : beat{};
    const beat rb = take ? r.read() : beat{};
    const auto e = d.clock(take, lb, rb, true);
    if (e.valid) {
      out.write(e.beat);
      ++written;
    }
  }
  return written;
}
#pragma GCC diagnostic pop

/// The frame function over arrays of `n` beats each (tests).
template <typename Params>
int disparity_frame(Disparity<Params>& d, const typename Params::pixel_beat* l,
                    const typename Params::pixel_beat* r, typename Params::disp_beat* out, int n,
                    long max_clocks) {
  ArrayIn<typename Params::pixel_beat> lv(l, n), rv(r, n);
  ArrayOut<typename Params::disp_beat> o(out);
  return disparity_frame(d, lv, rv, o, n, max_clocks);
}

}  // namespace scw::hls::disparity
