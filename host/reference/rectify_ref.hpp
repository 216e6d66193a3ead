// SPDX-License-Identifier: Apache-2.0
// Whole-image reference for the rectify stage: bilinear sampling in integers, straight from the
// spec formula (architecture.md 4.1), so the streaming model can be checked against it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "hls/rectify/rectify_params.hpp"

namespace scw::reference {

/// Bilinear blend of the four taps f00 (x0, y0), f10 (x0 + 1, y0), f01 (x0, y0 + 1),
/// f11 (x0 + 1, y0 + 1) at fractional offsets fx, fy in units of 1/S, S = 2^frac_bits:
/// (f00 (S-fx)(S-fy) + f10 fx (S-fy) + f01 (S-fx) fy + f11 fx fy + S*S/2) >> 2F.
/// The weights sum to S*S, so the result never exceeds 255 and needs no saturation.
inline std::uint8_t bilinear_reference(int f00, int f10, int f01, int f11, int fx, int fy,
                                       int frac_bits) {
  const std::int64_t s = std::int64_t{1} << frac_bits;
  const std::int64_t acc = f00 * (s - fx) * (s - fy) + f10 * fx * (s - fy) +
                           f01 * (s - fx) * fy + f11 * fx * fy + s * s / 2;
  return static_cast<std::uint8_t>(acc >> (2 * frac_bits));
}

/// Rectifies a row-major `width` x `height` raw image: output pixel (u, v) samples the raw
/// image at map[v * out_width + u] (signed fixed point, frac_bits fractional bits). Raw pixels
/// outside the image read as 0 (OpenCV BORDER_CONSTANT, value 0). Plain whole-image loops: it
/// shares no code with the streaming kernel or hls::rectify::decode_taps.
inline std::vector<std::uint8_t> rectify_reference(const std::uint8_t* raw, int width, int height,
                                                   const hls::rectify::MapPoint* map,
                                                   int out_width, int out_height,
                                                   int frac_bits) {
  const std::int64_t s = std::int64_t{1} << frac_bits;
  // floor(a / s) for negative a too (C++ division truncates toward zero).
  const auto floor_div = [s](std::int64_t a) { return a >= 0 ? a / s : -((-a + s - 1) / s); };
  const auto pixel = [&](std::int64_t x, std::int64_t y) -> int {
    if (x < 0 || x >= width || y < 0 || y >= height) return 0;
    return raw[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
               static_cast<std::size_t>(x)];
  };
  std::vector<std::uint8_t> out(static_cast<std::size_t>(out_width) *
                                static_cast<std::size_t>(out_height));
  for (int v = 0; v < out_height; ++v)
    for (int u = 0; u < out_width; ++u) {
      const std::size_t i = static_cast<std::size_t>(v) * static_cast<std::size_t>(out_width) +
                            static_cast<std::size_t>(u);
      const std::int64_t x = map[i].x, y = map[i].y;
      const std::int64_t x0 = floor_div(x), y0 = floor_div(y);
      const int fx = static_cast<int>(x - x0 * s), fy = static_cast<int>(y - y0 * s);
      out[i] = bilinear_reference(pixel(x0, y0), pixel(x0 + 1, y0), pixel(x0, y0 + 1),
                                  pixel(x0 + 1, y0 + 1), fx, fy, frac_bits);
    }
  return out;
}

}  // namespace scw::reference
