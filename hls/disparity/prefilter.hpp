// SPDX-License-Identifier: Apache-2.0
// cv::StereoBM's x-Sobel prefilter as a streaming kernel: one output row per input row.
#pragma once

#include <array>
#include <cstdint>

#include "hls/common/beat.hpp"

namespace scw::hls::disparity {

/// P(x, y) = clamp(g(x, y-1) + 2 g(x, y) + g(x, y+1), -cap, cap) + cap, g = I(x+1) - I(x-1);
/// rows -1 and H read as rows 1 and H - 2; columns 0 and W - 1, and the last row when H is odd,
/// are cap (docs/disparity.md). Output row v needs input rows up to v + 1, so a writer and a
/// reader share five row slots and a counter `avail` (rows written minus rows read, across
/// frames): the writer may run up to three rows ahead, the reader needs
/// min(2, H - v) rows ahead. The last row of a frame leaves while the next frame's first row
/// comes in, so frames stream back to back at one beat per clock. The caller reads before it
/// writes in a clock (read_allowed/read, then write), as a block RAM does.
template <typename Params>
class XSobel {
 public:
  static constexpr int P = Params::kPpc;
  static constexpr int W = Params::kMaxWidthPx;
  static constexpr int kSlots = 5;
  /// Clocks from a read to its beat in the RTL twin (rtl_models/disparity/
  /// scw_disparity_prefilter.sv: RAM read, the RAM's output register, row select, sum and
  /// clamp); read() itself returns the beat at once, so the RTL's out_valid_o is the read
  /// delayed by this many clocks.
  static constexpr int kReadLatency = 4;
  using beat = typename Params::pixel_beat;

  void configure(int width, int height, int cap) {
    width_ = width;
    height_ = height;
    cap_ = cap;
  }

  bool write_allowed() const { return avail_ <= 3; }
  bool read_allowed() const {
    const int left = height_ - out_y_;
    return avail_ >= (left < 2 ? left : 2);
  }

  void write(const beat& in) {
    for (int i = 0; i < P; ++i) buf_[in_slot_][in_x_ * P + i] = in.px[i];
    if (++in_x_ < width_ / P) return;
    in_x_ = 0;
    in_slot_ = (in_slot_ + 1) % kSlots;
    ++avail_;
    if (++in_y_ == height_) in_y_ = 0;
  }

  beat read() {
    beat out;
    const int v = out_y_;
    const int up = (out_slot_ + (v == 0 ? 1 : kSlots - 1)) % kSlots;       // row v - 1 (or 1)
    const int down = (out_slot_ + (v == height_ - 1 ? kSlots - 1 : 1)) % kSlots;  // v + 1
    const bool cap_row = (height_ % 2 == 1) && v == height_ - 1;
    for (int i = 0; i < P; ++i) {
      const int x = out_x_ * P + i;
      int value = cap_;
      if (!cap_row && x > 0 && x < width_ - 1) {
        const int s = g(up, x) + 2 * g(out_slot_, x) + g(down, x);
        value = (s < -cap_ ? -cap_ : (s > cap_ ? cap_ : s)) + cap_;
      }
      out.px[i] = static_cast<pixel_t>(value);
    }
    out.sof = out_x_ == 0 && v == 0;
    out.eol = out_x_ == width_ / P - 1;
    if (!out.eol) {
      ++out_x_;
      return out;
    }
    out_x_ = 0;
    out_slot_ = (out_slot_ + 1) % kSlots;
    --avail_;
    if (++out_y_ == height_) out_y_ = 0;
    return out;
  }

 private:
  int g(int slot, int x) const { return buf_[slot][x + 1] - buf_[slot][x - 1]; }

  std::array<std::array<pixel_t, W>, kSlots> buf_{};
  int width_ = 0, height_ = 0, cap_ = 31;
  int avail_ = 0;
  int in_x_ = 0, in_y_ = 0, in_slot_ = 0;
  int out_x_ = 0, out_y_ = 0, out_slot_ = 0;
};

}  // namespace scw::hls::disparity
