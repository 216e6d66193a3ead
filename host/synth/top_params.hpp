// SPDX-License-Identifier: Apache-2.0
// The scw_pipeline top's parameters at a build, by the RTL's names: what `scw synth` sets on the
// top and a pipeline vector set's manifest records for its replay.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace scw::host::synth {

/// `P` is an hls::pipeline::PipelineParams build; the FIFO depths are the top's defaults.
template <class P>
std::vector<std::pair<std::string, int>> top_params() {
  return {{"Ppc", P::kPpc},
          {"MaxWidthPx", P::kMaxWidthPx},
          {"MaxHeight", P::kMaxHeight},
          {"RectRows", P::kRectRows},
          {"GridLog2", P::kGridLog2},
          {"Window", P::kWindow},
          {"NumDisp", P::kNumDisp},
          {"MaxTilesX", P::kMaxTilesX},
          {"MaxTilesY", P::kMaxTilesY},
          {"LabelsPerTile", P::kLabelsPerTile},
          {"MaxObjects", P::kMaxObjects},
          {"MaxDisparityPx", P::kMaxDisparityPx}};
}

}  // namespace scw::host::synth
