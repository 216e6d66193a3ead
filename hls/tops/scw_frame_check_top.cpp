// SPDX-License-Identifier: Apache-2.0
// C-synthesis top of one camera's frame check (docs/pipeline.md): every raw beat on, each frame's
// flag (its geometry right or wrong) on a side stream.
#include "hls/pipeline/frame_check.hpp"
#include "hls/tops/tops.hpp"

using namespace scw::hls;        // NOLINT: the top's file names only the project's types
using namespace scw::hls::tops;  // NOLINT

void scw_frame_check_top(Pixels& in, Pixels& out, Flags& flags, pipeline::FrameCheckConfig cfg,
                         int n) {
  // clang-format off
#pragma HLS INTERFACE axis port=in
#pragma HLS INTERFACE axis port=out
#pragma HLS INTERFACE axis port=flags
#pragma HLS INTERFACE s_axilite port=cfg
#pragma HLS INTERFACE s_axilite port=n
#pragma HLS INTERFACE s_axilite port=return
  // clang-format on
  static pipeline::FrameCheck<Build::kPpc, Build::kMaxWidthPx, Build::kMaxHeight> kernel(
      cfg);  // configured by the first call
  pipeline::frame_check_frame(kernel, in, out, flags, n);
}
