// SPDX-License-Identifier: Apache-2.0
// Rectify kernel: a streaming bilinear remap through a window of raw rows kept on chip.
#pragma once

#include <array>
#include <cstdint>

#include "hls/common/beat.hpp"
#include "hls/common/force_inline.hpp"
#include "hls/common/stream.hpp"
#include "hls/rectify/map_taps.hpp"
#include "hls/rectify/rectify_params.hpp"

namespace scw::hls::rectify {

/// The body of an II=1 loop with non-blocking stream reads (one call of clock() per clock
/// cycle), the twin of rtl_models/rectify/scw_rectify.sv.
///
/// Two sides share a circular buffer of Rows raw rows and one counter, `avail` = raw rows
/// written minus output rows started-and-finished, counted across frames:
/// - the writer takes raw beats while avail + pending <= D + 1 (pending: the last beat of an
///   output row has been accepted but has not yet read the RAM);
/// - the reader takes one map beat per output beat while avail >= min(D, H - v) (output row v
///   needs raw rows up to v + D - 1, or the frame's last row);
/// so in steady state both move one beat per clock, D rows apart, and the next frame's first
/// rows are written while the last rows of a frame are read.
///
/// Geometry comes from the configuration; sof/eol are checked, never trusted: a misplaced
/// flag sets a sticky error bit. A sof in the middle of a frame is held: the writer marks the
/// rest of its frame as written (without data), the reader emits zeros for the rest of its
/// frame, and both start the new frame with the held beat, so the output is always a whole
/// W x H frame and the next frame is exact. A beat that should start a frame but has no sof is
/// dropped. A map tap that needs a raw row outside the window reads 0 and sets kErrMapWindow.
template <typename Params>
class Rectify {
 public:
  static constexpr int P = Params::kPpc;
  static constexpr int R = Params::kRows;
  static constexpr int F = Params::kFracBits;
  static constexpr int kMaxCols = Params::kMaxWidthPx / P;
  using raw_type = typename Params::pixel_beat;
  using map_type = typename Params::map_beat;
  using out_type = typename Params::pixel_beat;

  /// What the reader produced at this clock edge (at most one output beat).
  struct Emit {
    bool valid = false;
    out_type beat{};
  };

  explicit Rectify(const RectifyConfig& cfg = {}) : cfg_(cfg) {}

  const RectifyConfig& config() const { return cfg_; }
  std::uint8_t error() const { return err_; }

  /// The writer's ready, given `pending`.
  bool raw_ready(bool pending) const { return !skip_ && !raw_held_ && write_allowed(pending); }
  /// Whether the reader may start or continue its output beat this cycle.
  bool read_allowed() const {
    const int rows_left = cfg_.height - out_.row;
    return avail_ >= (cfg_.lead_rows < rows_left ? cfg_.lead_rows : rows_left);
  }
  /// The reader's ready for the map stream, given that the output pipeline advances.
  bool map_ready(bool advance) const {
    return advance && read_allowed() && !fill_ && !map_held_;
  }

  /// One clock edge. `raw_take` / `map_take`: a beat was accepted on that port (valid && ready
  /// as computed above, from the state before this edge). The reader reads the RAM before the
  /// writer writes it, as the RTL's block RAM does.
  Emit clock(bool pending, bool raw_take, const raw_type& raw, bool advance, bool map_take,
             const map_type& map) {
    // clang-format off
#pragma HLS INLINE
    // clang-format on
    const bool writer_may = write_allowed(pending);
    int d_avail = 0;
    Emit e;
    if (advance && read_allowed()) e = read_side(map_take, map, d_avail);
    write_side(writer_may, raw_take, raw, d_avail);
    avail_ += d_avail;
    return e;
  }

 private:
  int cols() const { return cfg_.width / P; }

  bool write_allowed(bool pending) const {
    return avail_ + (pending ? 1 : 0) <= cfg_.lead_rows + 1;
  }

  /// A place in the frame's beat raster and the circular row slot of its row.
  struct Cursor {
    int col = 0, row = 0, slot = 0;
    bool frame_start() const { return row == 0 && col == 0; }
    /// One beat on; true when that finished a row (col back to 0, next slot).
    bool step(int cols) {
      if (col != cols - 1) {
        ++col;
        return false;
      }
      col = 0;
      slot = (slot + 1) & (R - 1);
      return true;
    }
    /// After a finished row: the next row; true when that finished the frame.
    bool next_row(int height) {
      if (row == height - 1) {
        row = 0;
        return true;
      }
      ++row;
      return false;
    }
  };

  /// What a side does with a beat, given where its frame is (the resynchronisation rule).
  enum class Sync { kUse, kHold, kDrop };
  static Sync sync(bool sof, bool frame_start) {
    if (sof && !frame_start) return Sync::kHold;  // the frame was cut short: hold the beat
    if (!sof && frame_start) return Sync::kDrop;  // a frame starts with sof
    return Sync::kUse;
  }

  // ---- writer ------------------------------------------------------------------------------
  SCW_INLINE void write_side(bool may, bool take, const raw_type& raw, int& d_avail) {
    if (take) {
      const Sync what = sync(raw.sof, in_.frame_start());
      if (what != Sync::kUse) err_ |= kErrRawGeometry;
      if (what == Sync::kHold) {
        raw_held_ = true;
        held_raw_ = raw;
        skip_ = true;
      } else if (what == Sync::kUse) {
        write_beat(raw, d_avail);
      }
    } else if (skip_ && may) {
      blank_[in_.slot] = true;  // a row the frame did not send (or sent part of) reads 0
      in_.col = cols() - 1;  // one row of the interrupted frame per clock, no data
      in_.step(cols());
      row_done(d_avail);
    } else if (raw_held_ && may) {
      raw_held_ = false;
      write_beat(held_raw_, d_avail);
    }
  }

  SCW_INLINE void write_beat(const raw_type& raw, int& d_avail) {
    if (raw.eol != (in_.col == cols() - 1)) err_ |= kErrRawGeometry;
    const int slot = in_.slot;
    for (int i = 0; i < P; ++i) buf_[slot][in_.col * P + i] = raw.px[i];
    if (in_.step(cols())) {
      blank_[slot] = false;  // a row written to its end
      row_done(d_avail);
    }
  }

  void row_done(int& d_avail) {
    ++d_avail;
    if (in_.next_row(cfg_.height)) skip_ = false;
  }

  // ---- reader ------------------------------------------------------------------------------
  SCW_INLINE Emit read_side(bool take, const map_type& map, int& d_avail) {
    const bool frame_start = out_.frame_start();
    Emit e;
    if (fill_) {
      e.valid = true;  // zeros for the rest of an interrupted frame
    } else if (map_held_) {
      map_held_ = false;
      e = interpolate(held_map_);
    } else if (take) {
      const Sync what = sync(map.sof, frame_start);
      if (what != Sync::kUse) err_ |= kErrMapGeometry;
      if (what == Sync::kHold) {
        map_held_ = true;
        held_map_ = map;
        fill_ = true;
      } else if (what == Sync::kUse) {
        e = interpolate(map);
      }
    }
    if (!e.valid) return e;
    e.beat.sof = frame_start;
    e.beat.eol = out_.col == cols() - 1;
    if (out_.step(cols())) {
      --d_avail;
      if (out_.next_row(cfg_.height)) fill_ = false;
    }
    return e;
  }

  SCW_INLINE Emit interpolate(const map_type& map) {
    if (map.eol != (out_.col == cols() - 1)) err_ |= kErrMapGeometry;
    Emit e;
    e.valid = true;
    for (int i = 0; i < P; ++i) e.beat.px[i] = sample(map.px[i]);
    return e;
  }

  /// Bilinear sample, blended horizontally then vertically with a single rounding at the end:
  /// a = f00 S + (f10 - f00) fx = f00 (S - fx) + f10 fx exactly, likewise b; then
  /// (a S + (b - a) fy + S^2 / 2) >> 2F is the formula of architecture 4.1.
  SCW_INLINE pixel_t sample(const MapPoint& m) {
    // The four taps fall in four banks by row and column parity (see buf_), so one clock reads
    // them all. P-fold replication for the P lanes is left to the tool (not tried).
    // clang-format off
#pragma HLS ARRAY_PARTITION variable=buf_ cyclic factor=2 dim=1
#pragma HLS ARRAY_PARTITION variable=buf_ cyclic factor=2 dim=2
    // clang-format on
    const Taps t = decode_taps<F>(m, cfg_.width, cfg_.height);
    const int dy = t.y0 - out_.row;
    const bool use0 = t.row0 && in_row_window(dy, cfg_.lead_rows, R);
    const bool use1 = t.row1 && in_row_window(dy + 1, cfg_.lead_rows, R);
    if (use0 != t.row0 || use1 != t.row1) err_ |= kErrMapWindow;
    const int s0 = (out_.slot + dy) & (R - 1);
    const int s1 = (s0 + 1) & (R - 1);
    // A blank slot's row was never sent in this frame (a cut frame): it reads 0, whatever the
    // RAM holds from before (on a board: earlier frames, or power-up contents after reset).
    const bool live0 = use0 && !blank_[s0], live1 = use1 && !blank_[s1];
    const int f00 = live0 && t.col0 ? buf_[s0][t.x0] : 0;
    const int f10 = live0 && t.col1 ? buf_[s0][t.x0 + 1] : 0;
    const int f01 = live1 && t.col0 ? buf_[s1][t.x0] : 0;
    const int f11 = live1 && t.col1 ? buf_[s1][t.x0 + 1] : 0;
    const int a = (f00 << F) + (f10 - f00) * t.fx;
    const int b = (f01 << F) + (f11 - f01) * t.fx;
    return static_cast<pixel_t>(((a << F) + (b - a) * t.fy + (1 << (2 * F - 1))) >> (2 * F));
  }

  RectifyConfig cfg_;
  // The RTL splits this into 4 banks by row and column parity (the four taps always fall in
  // different banks) and keeps one copy per output lane:
  // ARRAY_PARTITION cyclic factor=2 on both dimensions, and P-fold replication.
  std::array<std::array<pixel_t, Params::kMaxWidthPx>, R> buf_{};
  // Per row slot: no row of data since reset or since a cut frame skipped it (the RTL's
  // blank_q, reset to all ones). Set by the skip, cleared when a row is written to its end; the
  // reader sees either from the next clock, as it sees the row itself.
  std::array<bool, R> blank_ = all_blank();
  static constexpr std::array<bool, R> all_blank() {
    std::array<bool, R> b{};
    for (auto& x : b) x = true;
    return b;
  }
  int avail_ = 0;
  std::uint8_t err_ = 0;
  // writer
  Cursor in_;
  bool skip_ = false, raw_held_ = false;
  raw_type held_raw_{};
  // reader
  Cursor out_;
  bool fill_ = false, map_held_ = false;
  map_type held_map_{};
};

// The loop label names the loop in HLS reports; g++ would call it unused.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-label"
/// Frames through the stage with no output stalls: `n` raw beats and `n` map beats (whole frames
/// of the configured size, back to back), `n` rectified beats to `out`; returns how many were
/// written (n, unless the input breaks the frame geometry and `max_clocks` runs out first). The
/// loop is one clock of the stage an iteration: each port takes its next beat when the stage is
/// ready for it, and every beat the reader forms is written. With the output never stalled, the
/// writer's look at the pipeline (`pending`) is whether the last beat formed closed a row. What an
/// HLS tool synthesises as the stage's top: the ports are hls::stream (or ArrayIn / ArrayOut).
template <typename Params, typename RawIn, typename MapIn, typename Out, if_port<Out> = 0>
int rectify_frame(Rectify<Params>& k, RawIn& raw, MapIn& map, Out& out, int n, long max_clocks) {
  // clang-format off
#pragma HLS INTERFACE axis port=raw
#pragma HLS INTERFACE axis port=map
#pragma HLS INTERFACE axis port=out
#pragma HLS INTERFACE s_axilite port=n
#pragma HLS INTERFACE s_axilite port=max_clocks
#pragma HLS INTERFACE s_axilite port=return
  // clang-format on
  using Kernel = Rectify<Params>;
  int written = 0;
  bool pending = false;
loop_clock:
  for (long c = 0; c < max_clocks && written < n; ++c) {
    // clang-format off
#pragma HLS PIPELINE II=1
    // clang-format on
    const bool raw_take = !raw.empty() && k.raw_ready(pending);
    const bool map_take = !map.empty() && k.map_ready(true);
    const typename Kernel::raw_type r = raw_take ? raw.read() : typename Kernel::raw_type{};
    const typename Kernel::map_type m = map_take ? map.read() : typename Kernel::map_type{};
    const auto e = k.clock(pending, raw_take, r, true, map_take, m);
    pending = e.valid && e.beat.eol;
    if (e.valid) {
      out.write(e.beat);
      ++written;
    }
  }
  return written;
}
#pragma GCC diagnostic pop

/// The frame function over arrays of `n` beats each (tests, vector sets).
template <typename Params>
int rectify_frame(Rectify<Params>& k, const typename Rectify<Params>::raw_type* raw,
                  const typename Rectify<Params>::map_type* map,
                  typename Rectify<Params>::out_type* out, int n, long max_clocks) {
  ArrayIn<typename Rectify<Params>::raw_type> r(raw, n);
  ArrayIn<typename Rectify<Params>::map_type> m(map, n);
  ArrayOut<typename Rectify<Params>::out_type> o(out);
  return rectify_frame(k, r, m, o, n, max_clocks);
}

}  // namespace scw::hls::rectify
