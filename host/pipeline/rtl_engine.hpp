// SPDX-License-Identifier: Apache-2.0
// `scw run --engine rtl`: the stages as the Verilated pipeline of a build that takes the frame.
#pragma once

#include <functional>
#include <utility>

#include "host/app/run.hpp"
#include "host/rectify/map_grid.hpp"

namespace scw::host::pipeline {

/// Both cameras' knots at a knot spacing of 2^grid_log2 px (rectify::grid_knots of a
/// calibration); empty: the pairs are rectified and the rectifiers run an identity map.
using KnotSource = std::function<rectify::StereoKnots(int grid_log2)>;

/// A StageEngine that streams each pair through every block of the pipeline as Verilated RTL
/// (sim::PipelineChain, all blocks RTL), with the first build that takes a width x height frame
/// and `o`'s window, disparity range and tiles. With `knots` the rectifiers run the
/// calibration's grid maps, their lead planned from the expanded maps (rectify::plan_for_stage).
/// Throws std::invalid_argument naming what each build takes when none does, or why the maps do
/// not fit the build's row window. `threads` 2 steps the chain on two threads (docs/sim.md).
app::StageEngine make_rtl_engine(const app::RunOptions& o, int width, int height,
                                 const KnotSource& knots = {}, int threads = 1);

}  // namespace scw::host::pipeline
