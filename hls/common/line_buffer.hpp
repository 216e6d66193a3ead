// SPDX-License-Identifier: Apache-2.0
// Line buffer kernel: each beat leaves with the same columns of the Rows-1 rows above it.
#pragma once

#include <array>
#include <cstdint>

#include "hls/common/beat.hpp"

namespace scw::hls {

/// The vertical window of one beat: rows[0] is the incoming row, rows[k] the row k above
/// (all zero above the top of the frame).
template <typename T, int P, int Rows>
struct ColumnBeat {
  static constexpr int kPixels = P;
  static constexpr int kRows = Rows;
  using value_type = T;

  std::array<std::array<T, P>, Rows> rows{};
  bool sof = false;
  bool eol = false;

  friend bool operator==(const ColumnBeat& a, const ColumnBeat& b) {
    return a.rows == b.rows && a.sof == b.sof && a.eol == b.eol;
  }
  friend bool operator!=(const ColumnBeat& a, const ColumnBeat& b) { return !(a == b); }
};

/// Compile-time parameters of a line buffer (the single source the RTL is checked against).
template <int P, int MaxWidthPx, int Rows>
struct LineBufferParams {
  static constexpr int kPpc = P;
  static constexpr int kMaxWidthPx = MaxWidthPx;
  static constexpr int kRows = Rows;
  static constexpr int kCols = MaxWidthPx / P;  // RAM depth in beats
  /// Cycles from accepting a beat to presenting it (RAM read + output register): shared by
  /// the RTL (scw_line_buffer), sim/ and the tests.
  static constexpr int kLatency = 2;
  static_assert(Rows >= 2, "a line buffer keeps at least one earlier row");
  static_assert(MaxWidthPx % P == 0 && kCols >= 2, "need MaxWidthPx % P == 0 and >= 2 beats");
};

/// Streaming line buffer, the body of an II=1 loop: `step()` takes one beat and returns it with
/// the Rows-1 rows above. Rows are as long as their `eol` says, up to MaxWidthPx; a longer row
/// or a `sof` before the previous row's `eol` sets the sticky `error()` and the kernel
/// resynchronises on the next `sof`. This is the twin of rtl_models/common/scw_line_buffer.sv.
template <typename T, typename Params>
class LineBuffer {
 public:
  static constexpr int P = Params::kPpc;
  static constexpr int kRows = Params::kRows;
  static constexpr int kCols = Params::kCols;
  using in_type = Beat<T, P>;
  using out_type = ColumnBeat<T, P, kRows>;

  out_type step(const in_type& in) {
    // clang-format off
#pragma HLS INLINE
    // clang-format on
    const int col = in.sof ? 0 : col_;
    const int row = in.sof ? 0 : row_;
    const bool in_range = col < kCols;
    if ((in.sof && col_ != 0) || !in_range) error_ = true;

    out_type out;
    out.sof = in.sof;
    out.eol = in.eol;
    out.rows[0] = in.px;
    for (int k = 1; k < kRows; ++k) {
      out.rows[k] = (in_range && row >= k) ? ram_[in_range ? col : 0][k - 1] : std::array<T, P>{};
    }
    if (in_range) {
      // Shift the column down one row: the oldest row drops out, the new row goes in on top.
      for (int k = kRows - 2; k > 0; --k) ram_[col][k] = ram_[col][k - 1];
      ram_[col][0] = in.px;
    }
    if (in.eol) {
      col_ = 0;
      row_ = row < kRows - 1 ? row + 1 : kRows - 1;
    } else {
      col_ = in_range ? col + 1 : col;
      row_ = row;
    }
    return out;
  }

  bool error() const { return error_; }

 private:
  std::array<std::array<std::array<T, P>, kRows - 1>, kCols> ram_{};  // one word per column
  int col_ = 0;  // beat column of the next beat, saturates at kCols
  int row_ = 0;  // rows seen in this frame, saturates at kRows - 1
  bool error_ = false;
};

}  // namespace scw::hls
