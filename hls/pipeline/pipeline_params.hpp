// SPDX-License-Identifier: Apache-2.0
// The whole pipeline's built parameters: one bundle per build, the one source of truth that the
// C++ chain (sim/pipeline_chain.hpp), the Verilated top (scw_pipeline) and `scw synth` share.
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

/// The thesis configuration (architecture section 2): 1280 x 480, window 21, 45 candidates
/// (20 .. 64), 64 raw rows in each rectifier, knots every 16 px, 8 x 4 labelling tiles of 32
/// labels, 256 objects, a reciprocal table up to 128 px.
template <int P>
using ThesisPipeline = PipelineParams<P, 1280, 480, 64, 4, 21, 45, 8, 4, 32, 256, 128>;

/// A small build for tests and CI (RTL compiles and runs in seconds): up to 128 x 96 (a crop
/// of the Tsukuba pair fits, disparities 0 .. 15), window 9, 16 candidates, 16 raw rows, knots
/// every 8 px, up to 4 x 2 tiles of 256 labels (4 tile columns for 4 lanes), 64 objects, codes
/// below 32 px.
template <int P>
using SmallPipeline = PipelineParams<P, 128, 96, 16, 3, 9, 16, 4, 2, 256, 64, 32>;

/// Tsukuba-sized (384 x 288), window 9, 16 candidates (0 .. 15): the bundled real pair.
using TsukubaPipeline = PipelineParams<1, 384, 288, 16, 4, 9, 16, 4, 4, 256, 64, 32>;

}  // namespace scw::hls::pipeline
