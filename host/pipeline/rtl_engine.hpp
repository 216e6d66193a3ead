// SPDX-License-Identifier: Apache-2.0
// `scw run --engine rtl`: the stages as the Verilated pipeline of a build that takes the frame.
#pragma once

#include "host/app/run.hpp"

namespace scw::host::pipeline {

/// A StageEngine that streams each rectified pair through every block of the pipeline as
/// Verilated RTL (sim::PipelineChain, all blocks RTL, the rectifiers on an identity map), with
/// the first build that takes a width x height frame and `o`'s window, disparity range and
/// tiles. Throws std::invalid_argument naming what each build takes when none does.
app::StageEngine make_rtl_engine(const app::RunOptions& o, int width, int height);

}  // namespace scw::host::pipeline
