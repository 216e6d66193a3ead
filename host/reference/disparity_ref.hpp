// SPDX-License-Identifier: Apache-2.0
// Whole-image reference for the disparity stage: a fresh N x N SAD for every pixel and every
// candidate (eq. 2.15 / 2.16) plus cv::StereoBM's prefilter, rejection rules and sub-pixel fit,
// each written out as an integer formula (docs/disparity.md), so the streaming model can be
// checked against it pixel for pixel.
#pragma once

#include <cstdint>
#include <vector>

#include "hls/disparity/disparity_params.hpp"

namespace scw::reference {

/// cv::StereoBM's PREFILTER_XSOBEL (OpenCV 4.6 prefilterXSobel) on a row-major 8-bit image:
///   out(x, y) = clamp(g(x, y-1) + 2 g(x, y) + g(x, y+1), -cap, cap) + cap,
///   g(x, y) = in(x+1, y) - in(x-1, y),
/// with rows -1 and H read as rows 1 and H-2 (BORDER_REFLECT_101). Columns 0 and W-1 are `cap`,
/// and so is the whole last row when H is odd (OpenCV filters rows in pairs and fills the odd
/// row out). Values 0 .. 2 cap.
std::vector<std::uint8_t> prefilter_xsobel_reference(const std::uint8_t* in, int width, int height,
                                                     int cap);

/// The SAD of one window: sum over |i|, |j| <= N/2 of |l(u+i, v+j) - r(u+i-d, v+j)| (eq. 2.15).
/// Every tap must lie inside both images.
int sad_reference(const std::uint8_t* l, const std::uint8_t* r, int width, int u, int v, int d,
                  int window_n);

/// Disparity of a row-major `width` x `height` pair for candidates d = cfg.dmin ..
/// cfg.dmin + num_disp - 1 with an N x N window (N = window_n, odd), one disp_t per pixel
/// (Q11.4 in 16 bits; docs/disparity.md "Semantics and the reference"):
///  - images: the raw pixels, or both x-Sobel prefiltered when cfg.prefilter;
///  - winner: the smallest SAD, the largest d on ties (eq. 2.16 with cv::StereoBM's tie rule: its
///    candidate index runs from the largest d down and keeps the first minimum);
///  - valid region: r <= v < H - r and r + max(DMax, 0) <= u < W - r + min(dmin, 0),
///    r = N/2 (every tap of every candidate inside both images); invalid_code(cfg) outside;
///    with cfg.edge_candidates = k (1 .. num_disp - 1) the region starts at r + dmin + k - 1
///    instead, and a column u left of r + DMax is decided among the candidates d <= u - r
///    alone (the left edge band);
///  - rejections (each off at 0, each to invalid_code(cfg)): texture, uniqueness, SAD limit;
///  - value: d * 16, or StereoBM's 4-bit sub-pixel fit when cfg.subpixel.
/// cfg.width and cfg.height are not read: `width` and `height` govern. Plain loops over every
/// window, no incremental sums, no code shared with hls::disparity.
std::vector<std::uint16_t> disparity_reference(const std::uint8_t* left, const std::uint8_t* right,
                                               int width, int height, int window_n, int num_disp,
                                               const hls::disparity::DisparityConfig& cfg);

/// StereoBM's sub-pixel value of a winner d with neighbour costs prev = SAD(d - 1),
/// best = SAD(d), next = SAD(d + 1) (OpenCV's p and n, whose candidate index runs downwards):
///   den = prev + next - 2 best + |prev - next|,
///   frac = den != 0 ? trunc((prev - next) * 256 / den) : 0      (|frac| <= 128),
///   out = floor((d * 256 + frac + 15) / 16)                    (d*16 - 8 .. d*16 + 8).
/// The winner at either end of the range gets no fraction (out = d * 16).
std::int32_t subpixel_reference(int d, int prev, int best, int next);

}  // namespace scw::reference
