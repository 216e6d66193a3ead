// SPDX-License-Identifier: Apache-2.0
// Disparity stage: compile-time parameters, run-time configuration and the output encoding.
#pragma once

#include <cstdint>

#include "hls/common/beat.hpp"
#include "hls/common/bits.hpp"

namespace scw::hls::disparity {

/// One output disparity, Q11.4 two's complement in 16 bits (disparity x 16, as cv::StereoBM's
/// CV_16S output). Valid pixels hold d * 16 (+ a 4-bit sub-pixel fraction when enabled);
/// invalid ones (outside the valid region, or rejected) hold `invalid_code(cfg)`.
using disp_t = std::uint16_t;

/// Built-in structure of one stage: the SAD window N x N (N odd; N rows of line buffer) and the
/// number of candidates evaluated in parallel; dmin and how many of them are used
/// (DisparityConfig::num_disp) are set at run time.
template <int P, int MaxWidthPx, int N, int NumDisp, int MaxHeight = 1024>
struct DisparityParams {
  static constexpr int kPpc = P;
  static constexpr int kMaxWidthPx = MaxWidthPx;
  static constexpr int kMaxHeight = MaxHeight;  // sizes the RTL's row counters
  static constexpr int kWindow = N;
  static constexpr int kRadius = N / 2;
  static constexpr int kNumDisp = NumDisp;
  using pixel_beat = Beat<pixel_t, P>;
  using disp_beat = Beat<disp_t, P>;
  static_assert(P == 1 || P == 2 || P == 4, "P must be 1, 2 or 4");
  static_assert(N % 2 == 1 && N >= 3, "the SAD window N must be odd and >= 3");
  static_assert(NumDisp >= 2, "at least two candidates");
  static_assert(MaxWidthPx % P == 0, "MaxWidthPx must be a multiple of P");
};

/// Run-time configuration (the RTL's cfg_* ports), stable while frames stream.
/// thesis mode = prefilter off, no rejection, no sub-pixel: plain SAD on the raw pixels
/// (eq. 2.15 / 2.16), invalid code 0. opencv mode = everything as cv::StereoBM defines it.
struct DisparityConfig {
  int width = 0;              // pixels, multiple of P
  int height = 0;             // rows
  int dmin = 0;               // smallest candidate (minDisparity), >= 0
  int num_disp = 0;           // candidates dmin .. dmin + num_disp - 1, 1 .. NumDisp (the built
                              // parallelism); 0 = all NumDisp. DMax = dmin + candidates - 1
  bool prefilter = false;     // x-Sobel prefilter with cap (StereoBM PREFILTER_XSOBEL)
  int prefilter_cap = 31;     // 1 .. 63
  int sad_limit = 0;          // > 0: reject when the minimum SAD exceeds it
  int texture_threshold = 0;  // > 0: reject when the window's texture sum is below it
  int uniqueness_ratio = 0;   // > 0: reject when another d (|d - best| > 1) has
                              //      SAD <= best + best * ratio / 100
  bool subpixel = false;      // 4-bit sub-pixel fraction (StereoBM's parabola-like fit)
  bool opencv_invalid = false;  // invalid code (dmin - 1) * 16 as StereoBM, else 0
  int edge_candidates = 0;      // the left edge band (docs/disparity.md, "The left edge"): a
                                // column whose window fits inside the right image for only
                                // the first k < n candidates is decided among those k when
                                // k >= edge_candidates; 0 (or >= n) = only with all n, as
                                // cv::StereoBM (its first dmin + n - 1 + R columns invalid)
};

/// Clocks from a beat entering the core's datapath to its window sums entering the decision
/// unit at `ppc` pixels a beat (scw_disparity_sums' Latency): the line-buffer read and its
/// output register, shift and absolute differences, column sums, C(x) - C(x - N), log2(ppc)
/// levels of prefix sums across the lanes, the window sums (docs/disparity.md).
constexpr int front_latency(int ppc) { return 7 + (ppc == 4 ? 2 : ppc == 2 ? 1 : 0); }

/// The result queue's depth in beats for n in flight: the smallest power of two >= n.
constexpr int queue_words(int n) { return pow2_at_least(n); }

/// The number of candidates a stage built for NumDisp evaluates under `c`.
template <int NumDisp>
constexpr int candidates(const DisparityConfig& c) {
  return c.num_disp > 0 && c.num_disp < NumDisp ? c.num_disp : NumDisp;
}

/// The fewest candidates a pixel at the left edge is decided among: edge_candidates, or all
/// candidates<NumDisp>(c) when it is 0 or above them.
template <int NumDisp>
constexpr int edge_min(const DisparityConfig& c) {
  const int n = candidates<NumDisp>(c);
  return c.edge_candidates > 0 && c.edge_candidates < n ? c.edge_candidates : n;
}

/// The candidates whose window lies inside the right image at output column u: d = dmin + k
/// needs u - R - d >= 0, so k < u - R - dmin + 1 (at most NumDisp; below 1: none).
template <int NumDisp>
constexpr int edge_limit(const DisparityConfig& c, int u, int radius) {
  const int k = u - radius - c.dmin + 1;
  return k < 0 ? 0 : k > NumDisp ? NumDisp : k;
}

/// The code of an invalid pixel.
constexpr disp_t invalid_code(const DisparityConfig& c) {
  return c.opencv_invalid ? static_cast<disp_t>(static_cast<std::int16_t>((c.dmin - 1) * 16)) : 0;
}

/// The two named modes of `scw disparity --mode` for a window and a range.
inline DisparityConfig thesis_mode(int width, int height, int dmin) {
  DisparityConfig c;
  c.width = width;
  c.height = height;
  c.dmin = dmin;
  return c;
}
/// cv::StereoBM's defaults: prefilter cap 31, texture threshold 10, uniqueness ratio 15.
inline DisparityConfig opencv_mode(int width, int height, int dmin, int prefilter_cap = 31,
                                   int texture_threshold = 10, int uniqueness_ratio = 15) {
  DisparityConfig c;
  c.width = width;
  c.height = height;
  c.dmin = dmin;
  c.prefilter = true;
  c.prefilter_cap = prefilter_cap;
  c.texture_threshold = texture_threshold;
  c.uniqueness_ratio = uniqueness_ratio;
  c.subpixel = true;
  c.opencv_invalid = true;
  return c;
}

}  // namespace scw::hls::disparity
