// SPDX-License-Identifier: Apache-2.0
// The whole pipeline's built parameters: one bundle per build, the one source of truth that the
// C++ chain (sim/pipeline/pipeline_chain.hpp), the Verilated top (scw_pipeline) and `scw synth` share.
#pragma once

#include "hls/disparity/disparity_params.hpp"
#include "hls/ground/ground_params.hpp"
#include "hls/labelling/labelling_params.hpp"
#include "hls/rectify/map_grid.hpp"
#include "hls/rectify/rectify_params.hpp"
#include "hls/road/road_params.hpp"
#include "hls/warning/warning_params.hpp"

namespace scw::hls::pipeline {

/// Two rectifiers fed by map-grid expanders, disparity, labelling and warning. Everything the
/// RTL top takes as a parameter, by the RTL's names.
template <int P, int MaxWidthPx, int MaxHeight, int RectRows, int GridLog2, int Window,
          int NumDisp, int MaxTilesX, int MaxTilesY, int LabelsPerTile, int MaxObjects,
          int MaxDisparityPx>
struct PipelineParams {
  static constexpr int kPpc = P;
  static constexpr int kMaxWidthPx = MaxWidthPx;
  static constexpr int kMaxHeight = MaxHeight;
  static constexpr int kRectRows = RectRows;
  static constexpr int kGridLog2 = GridLog2;
  static constexpr int kWindow = Window;
  static constexpr int kNumDisp = NumDisp;
  static constexpr int kMaxTilesX = MaxTilesX;
  static constexpr int kMaxTilesY = MaxTilesY;
  static constexpr int kLabelsPerTile = LabelsPerTile;
  static constexpr int kMaxObjects = MaxObjects;
  static constexpr int kMaxDisparityPx = MaxDisparityPx;

  using rectify = ::scw::hls::rectify::RectifyParams<P, MaxWidthPx, MaxHeight, RectRows>;
  using map_grid = ::scw::hls::rectify::MapGridParams<P, MaxWidthPx, MaxHeight, GridLog2>;
  using disparity = ::scw::hls::disparity::DisparityParams<P, MaxWidthPx, Window, NumDisp, MaxHeight>;
  /// P lanes: the disparity beats go in whole, each lane labelling a strip of tile columns.
  using labelling = ::scw::hls::labelling::LabellingParams<MaxWidthPx, MaxHeight, MaxTilesX,
                                                           MaxTilesY, LabelsPerTile, MaxObjects, P>;
  using warning = ::scw::hls::warning::WarningParams<MaxDisparityPx>;
  /// The road stage between disparity and labelling: P disparities a beat, as both take them.
  using road = ::scw::hls::road::RoadParams<P, MaxWidthPx, MaxHeight>;
  /// The optional ground-removal filter (thesis 6.2) between disparity and labelling: one pixel
  /// per beat, so only at P = 1.
  using ground = ::scw::hls::ground::GroundParams<MaxWidthPx>;
};

/// The builds: `ThesisPipeline<P>`, `SmallPipeline<P>`, `TsukubaPipeline<P>`, one for each row of
/// pipeline_configs.def (what each is for is written there), the file CMake Verilates them from.
#define SCW_PIPELINE_CONFIG(Name, ...) \
  template <int P>                      \
  using Name##Pipeline = PipelineParams<P, __VA_ARGS__>;
#include "hls/pipeline/pipeline_configs.def"
#undef SCW_PIPELINE_CONFIG

}  // namespace scw::hls::pipeline
