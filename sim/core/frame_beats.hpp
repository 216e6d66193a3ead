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

}  // namespace scw::sim
