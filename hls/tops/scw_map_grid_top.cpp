// SPDX-License-Identifier: Apache-2.0
// C-synthesis top of one camera's map-grid expander (docs/rectify.md): with `cols` > 0 the call
// first loads cols x rows knots (the knot port, once before the first frame), then streams `n` map
// beats.
#include "hls/rectify/map_grid.hpp"
#include "hls/tops/tops.hpp"

using namespace scw::hls;        // NOLINT: the top's file names only the project's types
using namespace scw::hls::tops;  // NOLINT

void scw_map_grid_top(const rectify::KnotPoint knots[kKnots], int cols, int rows, Maps& out,
                      rectify::MapGridConfig cfg, int n) {
  // clang-format off
#pragma HLS INTERFACE m_axi port=knots offset=slave depth=kKnots
#pragma HLS INTERFACE axis port=out
#pragma HLS INTERFACE s_axilite port=cols
#pragma HLS INTERFACE s_axilite port=rows
#pragma HLS INTERFACE s_axilite port=cfg
#pragma HLS INTERFACE s_axilite port=n
#pragma HLS INTERFACE s_axilite port=return
  // clang-format on
  static rectify::MapGrid<Build::map_grid> kernel(cfg);  // configured by the first call
  if (cols > 0) rectify::map_grid_load(kernel, knots, cols, rows);
  rectify::map_grid_frame(kernel, out, n);
}
