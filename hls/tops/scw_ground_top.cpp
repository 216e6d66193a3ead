// SPDX-License-Identifier: Apache-2.0
// C-synthesis top of the optional ground filter (docs/ground.md): `n` disparity beats in, the same
// beats with ground pixels cleared out; its column window kept between calls.
#include "hls/ground/ground.hpp"
#include "hls/tops/tops.hpp"

using namespace scw::hls;        // NOLINT: the top's file names only the project's types
using namespace scw::hls::tops;  // NOLINT

void scw_ground_top(GroundIn& in, GroundOut& out, ground::GroundConfig cfg, int n) {
  // clang-format off
#pragma HLS INTERFACE axis port=in
#pragma HLS INTERFACE axis port=out
#pragma HLS INTERFACE s_axilite port=cfg
#pragma HLS INTERFACE s_axilite port=n
#pragma HLS INTERFACE s_axilite port=return
  // clang-format on
  static ground::Ground<Build::ground> kernel(cfg);  // configured by the first call
  ground::ground_frame(kernel, in, out, n);
}
