// SPDX-License-Identifier: Apache-2.0
// C-synthesis top of the whole pipeline (docs/hls.md, "The pipeline top"): a frame of each camera
// in, its result (with both input flags) and its object table out, the stage tops as DATAFLOW
// processes. With `cols` > 0 the call first loads both cameras' knots (the knot port).
#include "hls/pipeline/pipeline_top.hpp"
#include "hls/tops/tops.hpp"

using namespace scw::hls;        // NOLINT: the top's file names only the project's types
using namespace scw::hls::tops;  // NOLINT

void scw_pipeline_top(Pixels& left, Pixels& right, PipelineResults& result, Words& table,
                      const rectify::KnotPoint knots_left[kKnots],
                      const rectify::KnotPoint knots_right[kKnots], int cols, int rows,
                      pipeline::PipelineConfig cfg) {
  // clang-format off
#pragma HLS INTERFACE axis port=left
#pragma HLS INTERFACE axis port=right
#pragma HLS INTERFACE axis port=result
#pragma HLS INTERFACE axis port=table
#pragma HLS INTERFACE m_axi port=knots_left offset=slave depth=kKnots
#pragma HLS INTERFACE m_axi port=knots_right offset=slave depth=kKnots
#pragma HLS INTERFACE s_axilite port=cols
#pragma HLS INTERFACE s_axilite port=rows
#pragma HLS INTERFACE s_axilite port=cfg
#pragma HLS INTERFACE ap_ctrl_chain port=return
  // clang-format on
  static pipeline::PipelineStages<Build> kernel(cfg);  // configured by the first call
  if (cols > 0) pipeline::pipeline_load_knots(kernel, knots_left, knots_right, cols, rows);
  pipeline::pipeline_frame(kernel, left, right, result, table);
}
