// SPDX-License-Identifier: Apache-2.0
// An image (pixels, map points, ...) as the beats of one frame: raster order, sof and eol set.
#pragma once

#include <cstdint>
#include <vector>

#include "hls/common/beat.hpp"

namespace scw::sim {

/// `values` is row-major, `width` x `height`, contiguous; `width % B::kPixels == 0`. `B` is any
/// beat with `px`, `sof` and `eol` (hls::Beat, hls::rectify::MapBeat).
template <typename B>
std::vector<B> frame_beats_of(const typename B::value_type* values, int width, int height) {
  constexpr int P = B::kPixels;
  std::vector<B> v;
  v.reserve(static_cast<std::size_t>(width / P * height));
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; x += P) {
      B b;
      for (int i = 0; i < P; ++i) b.px[i] = values[static_cast<std::size_t>(y) * width + x + i];
      b.sof = x == 0 && y == 0;
      b.eol = x + P == width;
      v.push_back(b);
    }
  return v;
}

/// A grey image as pixel beats.
template <int P>
std::vector<hls::Beat<std::uint8_t, P>> frame_beats(const std::uint8_t* img, int width,
                                                    int height) {
  return frame_beats_of<hls::Beat<std::uint8_t, P>>(img, width, height);
}

/// The beats frame_beats_of would make, read one at a time with a stream's read side (the
/// stage tops' port, hls/common/stream.hpp): a whole-image runner feeds a frame function from
/// the image itself, with no vector of beats in between.
template <typename B>
class FrameBeatsIn {
 public:
  FrameBeatsIn(const typename B::value_type* values, int width, int height)
      : values_(values), cols_(width / B::kPixels), rows_(height) {}
  bool empty() const { return row_ >= rows_; }
  B read() {
    B b;
    for (int i = 0; i < B::kPixels; ++i) b.px[i] = values_[i];
    values_ += B::kPixels;
    b.sof = col_ == 0 && row_ == 0;
    b.eol = col_ == cols_ - 1;
    if (b.eol) {
      col_ = 0;
      ++row_;
    } else {
      ++col_;
    }
    return b;
  }

 private:
  const typename B::value_type* values_;
  int cols_, rows_, col_ = 0, row_ = 0;
};

/// A row-major image written beat by beat with a stream's write side: the pixels only (the
/// caller checks the frame's geometry by the count). The caller sizes the image.
template <typename B, typename T = typename B::value_type>
class FrameBeatsOut {
 public:
  explicit FrameBeatsOut(T* values) : values_(values) {}
  bool full() const { return false; }
  void write(const B& b) {
    for (int i = 0; i < B::kPixels; ++i) values_[i] = static_cast<T>(b.px[i]);
    values_ += B::kPixels;
  }

 private:
  T* values_;
};

/// The clocks a whole-frame top loop (rectify_frame, disparity_frame) may take for a frame of
/// `beats` beats before the caller calls the stage stuck: a frame takes about `beats` clocks and
/// a few rows more, so this bound is only ever reached by a stage that stopped.
constexpr long frame_clock_limit(long beats) { return 4L * 3 * beats + 100000; }

}  // namespace scw::sim
