// SPDX-License-Identifier: Apache-2.0
// C-synthesis top of the labelling stage (docs/labelling.md): disparity beats in until `frames`
// frames' object tables (each closed by its status word) are out; label RAMs and descriptors kept.
#include "hls/labelling/labelling.hpp"
#include "hls/tops/tops.hpp"

using namespace scw::hls;        // NOLINT: the top's file names only the project's types
using namespace scw::hls::tops;  // NOLINT

void scw_labelling_top(LabellingIn& in, Words& out, labelling::LabellingConfig cfg, int frames) {
  // clang-format off
#pragma HLS INTERFACE axis port=in
#pragma HLS INTERFACE axis port=out
#pragma HLS INTERFACE s_axilite port=cfg
#pragma HLS INTERFACE s_axilite port=frames
#pragma HLS INTERFACE s_axilite port=return
  // clang-format on
  static labelling::Labelling<Build::labelling> kernel(cfg);  // configured by the first call
  labelling::labelling_frame(kernel, in, out, frames * kWords, frames,
                             frames * (4L * kFrameBeats + 100000));
}
