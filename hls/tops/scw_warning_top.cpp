// SPDX-License-Identifier: Apache-2.0
// C-synthesis top of the warning stage (docs/warning.md): `frames` object tables in (with
// cfg.road_height, one road line a frame beside them), one frame result a frame out.
#include "hls/tops/tops.hpp"
#include "hls/warning/warning.hpp"

using namespace scw::hls;        // NOLINT: the top's file names only the project's types
using namespace scw::hls::tops;  // NOLINT

void scw_warning_top(Words& in, RoadLines& roads, Results& out, warning::WarningConfig cfg,
                     int frames) {
  // clang-format off
#pragma HLS INTERFACE axis port=in
#pragma HLS INTERFACE axis port=roads
#pragma HLS INTERFACE axis port=out
#pragma HLS INTERFACE s_axilite port=cfg
#pragma HLS INTERFACE s_axilite port=frames
#pragma HLS INTERFACE s_axilite port=return
  // clang-format on
  static warning::Warning<Build::warning> kernel(cfg);  // configured by the first call
  warning::warning_frame(kernel, in, frames, out, roads,
                         frames * (static_cast<long>(kWords) + warning::kLatency));
}
