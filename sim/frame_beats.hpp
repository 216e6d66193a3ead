// SPDX-License-Identifier: Apache-2.0
// A grey image as the beats of one frame: P pixels per beat, raster order, sof and eol set.
#pragma once

#include <cstdint>
#include <vector>

#include "hls/common/beat.hpp"

namespace scw::sim {

/// `img` is row-major, `width` x `height`, contiguous; `width % P == 0`.
template <int P>
std::vector<hls::Beat<std::uint8_t, P>> frame_beats(const std::uint8_t* img, int width,
                                                    int height) {
  std::vector<hls::Beat<std::uint8_t, P>> v;
  v.reserve(static_cast<std::size_t>(width / P * height));
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; x += P) {
      hls::Beat<std::uint8_t, P> b;
      for (int i = 0; i < P; ++i) b.px[i] = img[static_cast<std::size_t>(y) * width + x + i];
      b.sof = x == 0 && y == 0;
      b.eol = x + P == width;
      v.push_back(b);
    }
  return v;
}

}  // namespace scw::sim
