// SPDX-License-Identifier: Apache-2.0
// C-synthesis top of the disparity stage (docs/disparity.md): `n` beats of both rectified cameras
// in, `n` disparity beats out; its line buffers and column sums kept between calls.
#include "hls/disparity/disparity.hpp"
#include "hls/tops/tops.hpp"

using namespace scw::hls;        // NOLINT: the top's file names only the project's types
using namespace scw::hls::tops;  // NOLINT

void scw_disparity_top(Pixels& left, Pixels& right, Disparities& out,
                       disparity::DisparityConfig cfg, int n) {
  // clang-format off
#pragma HLS INTERFACE axis port=left
#pragma HLS INTERFACE axis port=right
#pragma HLS INTERFACE axis port=out
#pragma HLS INTERFACE s_axilite port=cfg
#pragma HLS INTERFACE s_axilite port=n
#pragma HLS INTERFACE s_axilite port=return
  // clang-format on
  static disparity::Disparity<Build::disparity> kernel(cfg);  // configured by the first call
  disparity::disparity_frame(kernel, left, right, out, n, 4L * n + 100000);
}
