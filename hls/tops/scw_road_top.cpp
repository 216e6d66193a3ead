// SPDX-License-Identifier: Apache-2.0
// C-synthesis top of the road stage (docs/road.md): `n` disparity beats in, the road's pixels
// removed out, and at each frame's first beat the line that frame is gated with; the sums and the
// line kept.
#include "hls/road/road.hpp"
#include "hls/tops/tops.hpp"

using namespace scw::hls;        // NOLINT: the top's file names only the project's types
using namespace scw::hls::tops;  // NOLINT

void scw_road_top(RoadIn& in, RoadOut& out, RoadLines& lines, road::RoadConfig cfg, int n) {
  // clang-format off
#pragma HLS INTERFACE axis port=in
#pragma HLS INTERFACE axis port=out
#pragma HLS INTERFACE axis port=lines
#pragma HLS INTERFACE s_axilite port=cfg
#pragma HLS INTERFACE s_axilite port=n
#pragma HLS INTERFACE s_axilite port=return
  // clang-format on
  static road::Road<Build::road> kernel(cfg);  // configured by the first call
  road::road_frame(kernel, in, out, lines, n);
}
