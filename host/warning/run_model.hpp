// SPDX-License-Identifier: Apache-2.0
// Runs the warning model over one frame's object table (no stalls): what `scw run`, the golden
// vectors and the real-data checks use.
#pragma once

#include <cstdint>
#include <vector>

#include "hls/labelling/labelling_params.hpp"
#include "hls/warning/warning_params.hpp"

namespace scw::warning {

using hls::warning::FrameResult;
using hls::warning::WarningConfig;

/// The host's build of the stage: the reciprocal table covers disparities below 256 px.
constexpr int kHostMaxDisparityPx = 256;
using HostParams = hls::warning::WarningParams<kHostMaxDisparityPx>;

/// The object table as the labelling stage emits it: the objects, then the status word (last).
std::vector<hls::labelling::LabelPacket> table_words(
    const std::vector<hls::labelling::Object>& objects, const hls::labelling::FrameStatus& status);

/// One frame's words through the model, the output always taken. Returns the frame result and
/// the clocks from the first word's acceptance to the result in `*cycles` if given. Throws
/// std::invalid_argument (naming the field) for a config the host build cannot take, and
/// std::logic_error if the words close no frame.
/// With `road` the stage measures heights above it (cfg.road_height, the pipeline's way): the
/// frame's first word is taken with it.
FrameResult run_warning(const std::vector<hls::labelling::LabelPacket>& words,
                        const WarningConfig& cfg, std::int64_t* cycles = nullptr,
                        const hls::warning::RoadLine* road = nullptr);

/// The per-object view of the same arithmetic (hls::warning::evaluate at the host build), above
/// `road` when given.
hls::warning::ObjectEval evaluate_object(const hls::labelling::Object& o, const WarningConfig& cfg,
                                         const hls::warning::RoadLine* road = nullptr);

}  // namespace scw::warning
