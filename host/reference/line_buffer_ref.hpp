// SPDX-License-Identifier: Apache-2.0
// Whole-image reference for the line buffer: each beat with the pixels k rows above it.
#pragma once

#include <cstdint>
#include <vector>

#include "hls/common/line_buffer.hpp"

namespace scw::reference {

/// Indexes the image directly (no streaming state), so it shares nothing with hls::LineBuffer.
/// `img` is row-major, `width` x `height`, contiguous; `width % P == 0`.
template <int P, int Rows>
std::vector<hls::ColumnBeat<std::uint8_t, P, Rows>> line_buffer_reference(const std::uint8_t* img,
                                                                          int width, int height) {
  std::vector<hls::ColumnBeat<std::uint8_t, P, Rows>> out;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; x += P) {
      hls::ColumnBeat<std::uint8_t, P, Rows> b;
      for (int k = 0; k < Rows; ++k)
        for (int i = 0; i < P; ++i)
          b.rows[k][i] = y - k >= 0 ? img[static_cast<std::size_t>(y - k) * width + x + i] : 0;
      b.sof = x == 0 && y == 0;
      b.eol = x + P == width;
      out.push_back(b);
    }
  return out;
}

}  // namespace scw::reference
