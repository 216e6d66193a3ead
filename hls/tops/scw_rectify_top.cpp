// SPDX-License-Identifier: Apache-2.0
// C-synthesis top of one camera's rectifier (docs/rectify.md): `n` raw beats and `n` map beats
// (from the map grid) in, `n` rectified beats out; its row buffer kept between calls.
#include "hls/rectify/rectify.hpp"
#include "hls/tops/tops.hpp"

using namespace scw::hls;        // NOLINT: the top's file names only the project's types
using namespace scw::hls::tops;  // NOLINT

void scw_rectify_top(Pixels& raw, Maps& map, Pixels& out, rectify::RectifyConfig cfg, int n) {
  // clang-format off
#pragma HLS INTERFACE axis port=raw
#pragma HLS INTERFACE axis port=map
#pragma HLS INTERFACE axis port=out
#pragma HLS INTERFACE s_axilite port=cfg
#pragma HLS INTERFACE s_axilite port=n
#pragma HLS INTERFACE s_axilite port=return
  // clang-format on
  static rectify::Rectify<Build::rectify> kernel(cfg);  // configured by the first call
  rectify::rectify_frame(kernel, raw, map, out, n, 4L * n + 100000);
}
