// SPDX-License-Identifier: Apache-2.0
// The run-time settings of the whole pipeline: every stage's configuration, the cfg ports of
// rtl_models/pipeline/scw_pipeline.sv. The HLS top (pipeline_top.hpp) takes it; the simulator's
// setup (sim/pipeline/pipeline_setup.hpp) extends it.
#pragma once

#include "hls/disparity/disparity_params.hpp"
#include "hls/labelling/labelling_params.hpp"
#include "hls/road/road_params.hpp"
#include "hls/warning/warning_params.hpp"

namespace scw::hls::pipeline {

/// The run-time settings of every stage (the RTL top's cfg ports), stable while frames stream.
/// Width and height are the frame's for every stage; the disparity and labelling sizes and the
/// warning stage's road_height are taken from here, as the RTL top wires them.
struct PipelineConfig {
  int width = 0, height = 0;
  int lead_rows = 1;  // the rectifiers' D (host/rectify plans it from the maps)
  disparity::DisparityConfig disparity;  // width and height are taken from above
  /// The road stage (docs/road.md). The default configuration removes nothing: its nominal
  /// road is flat at 0 and no fitted slope is plausible (host/road/setup.hpp makes a real one).
  road::RoadConfig road;
  labelling::LabellingConfig labelling;
  warning::WarningConfig warning;

  disparity::DisparityConfig disparity_config() const {
    auto c = disparity;
    c.width = width;
    c.height = height;
    return c;
  }
  labelling::LabellingConfig labelling_config() const {
    auto c = labelling;
    c.width = width;
    c.height = height;
    return c;
  }
  warning::WarningConfig warning_config() const {
    auto c = warning;
    c.road_height = true;  // the top's warning stage measures heights above the road's lines
    return c;
  }
};

}  // namespace scw::hls::pipeline
