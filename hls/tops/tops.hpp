// SPDX-License-Identifier: Apache-2.0
// The C-synthesis tops (docs/hls.md, "The C-synthesis tops"): one plain function a stage, and
// one for the whole pipeline, each in its own file of this folder, as an HLS tool's `set_top`
// and a C-simulation test bench want them. Each fixes the build, keeps its kernel `static`
// (configured by the first call) and calls the stage's frame function.
//
// The build: the thesis configuration at P = 1 unless the tool's -cflags say otherwise
// (-DSCW_HLS_BUILD="scw::hls::pipeline::SmallPipeline<2>", any row of
// hls/pipeline/pipeline_configs.def), so a top's parameters are the RTL builds' numbers.
#pragma once

#include "hls/common/stream.hpp"
#include "hls/disparity/disparity_params.hpp"
#include "hls/ground/ground_params.hpp"
#include "hls/labelling/labelling_params.hpp"
#include "hls/pipeline/frame_check.hpp"
#include "hls/pipeline/pipeline_config.hpp"
#include "hls/pipeline/pipeline_params.hpp"
#include "hls/pipeline/pipeline_result.hpp"
#include "hls/rectify/map_grid.hpp"
#include "hls/rectify/rectify_params.hpp"
#include "hls/road/road_params.hpp"
#include "hls/warning/warning_params.hpp"

#ifndef SCW_HLS_BUILD
#define SCW_HLS_BUILD ::scw::hls::pipeline::ThesisPipeline<1>
#endif

namespace scw::hls::tops {
using Build = SCW_HLS_BUILD;
/// The depth of a frame's stream ports in g++ C simulation (a vendor stream ignores it): a test
/// bench writes a whole frame before the call.
inline constexpr int kFrameBeats = Build::kMaxWidthPx / Build::kPpc * Build::kMaxHeight;
inline constexpr int kWords = Build::kMaxObjects + 1;  // a frame's objects and its status word
inline constexpr int kKnots = Build::map_grid::kMaxKnotCols * Build::map_grid::kMaxKnotRows;

using Pixels = stream<Build::rectify::pixel_beat, kFrameBeats>;  // raw or rectified
using Maps = stream<Build::rectify::map_beat, kFrameBeats>;
using Disparities = stream<Build::disparity::disp_beat, kFrameBeats>;
using RoadIn = stream<Build::road::in_beat, kFrameBeats>;
using RoadOut = stream<Build::road::out_beat, kFrameBeats>;
using GroundIn = stream<Build::ground::in_beat, kFrameBeats>;
using GroundOut = stream<Build::ground::out_beat, kFrameBeats>;
using LabellingIn = stream<Build::labelling::in_beat, kFrameBeats>;
using Words = stream<labelling::LabelPacket, kWords>;
using RoadLines = stream<road::Line, 4>;
using Flags = stream<pipeline::FrameFlagPacket, 4>;
using Results = stream<warning::ResultPacket, 2>;
using PipelineResults = stream<pipeline::PipelineResultPacket, 2>;
}  // namespace scw::hls::tops

// One camera's frame check: `n` raw beats in and on, each frame's flag on `flags`.
void scw_frame_check_top(scw::hls::tops::Pixels& in, scw::hls::tops::Pixels& out,
                         scw::hls::tops::Flags& flags, scw::hls::pipeline::FrameCheckConfig cfg,
                         int n);
// One camera's map grid: with `cols` > 0 first load cols x rows knots, then `n` map beats out.
void scw_map_grid_top(const scw::hls::rectify::KnotPoint knots[scw::hls::tops::kKnots], int cols,
                      int rows, scw::hls::tops::Maps& out, scw::hls::rectify::MapGridConfig cfg,
                      int n);
// One camera's rectifier: `n` raw and `n` map beats in, `n` rectified beats out.
void scw_rectify_top(scw::hls::tops::Pixels& raw, scw::hls::tops::Maps& map,
                     scw::hls::tops::Pixels& out, scw::hls::rectify::RectifyConfig cfg, int n);
// Disparity: `n` beats of both rectified cameras in, `n` disparity beats out.
void scw_disparity_top(scw::hls::tops::Pixels& left, scw::hls::tops::Pixels& right,
                       scw::hls::tops::Disparities& out, scw::hls::disparity::DisparityConfig cfg,
                       int n);
// Road: `n` disparity beats in, the road's pixels removed out, each frame's line on `lines`.
void scw_road_top(scw::hls::tops::RoadIn& in, scw::hls::tops::RoadOut& out,
                  scw::hls::tops::RoadLines& lines, scw::hls::road::RoadConfig cfg, int n);
// The optional ground filter: `n` disparity beats in, ground pixels cleared out.
void scw_ground_top(scw::hls::tops::GroundIn& in, scw::hls::tops::GroundOut& out,
                    scw::hls::ground::GroundConfig cfg, int n);
// Labelling: disparity beats in until `frames` object tables (status word last) are out.
void scw_labelling_top(scw::hls::tops::LabellingIn& in, scw::hls::tops::Words& out,
                       scw::hls::labelling::LabellingConfig cfg, int frames);
// Warning: `frames` object tables (and with cfg.road_height their road lines) in, a result each.
void scw_warning_top(scw::hls::tops::Words& in, scw::hls::tops::RoadLines& roads,
                     scw::hls::tops::Results& out, scw::hls::warning::WarningConfig cfg,
                     int frames);
// The whole pipeline: a frame of each camera in, its result and object table out; with
// `cols` > 0 both cameras' knots are loaded first.
void scw_pipeline_top(scw::hls::tops::Pixels& left, scw::hls::tops::Pixels& right,
                      scw::hls::tops::PipelineResults& result, scw::hls::tops::Words& table,
                      const scw::hls::rectify::KnotPoint knots_left[scw::hls::tops::kKnots],
                      const scw::hls::rectify::KnotPoint knots_right[scw::hls::tops::kKnots],
                      int cols, int rows, scw::hls::pipeline::PipelineConfig cfg);
