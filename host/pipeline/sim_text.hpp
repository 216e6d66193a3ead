// SPDX-License-Identifier: Apache-2.0
// `scw sim`'s report as text: per-stage busy time, frame period and latency beside the thesis's
// Table 5.7, each block's span, the FIFOs' fill and every frame's result.
#pragma once

#include <cstddef>
#include <ostream>

#include "host/pipeline/sim_run.hpp"

namespace scw::host::pipeline {

/// Prints `r`; its frames are numbered from `first_frame` (a segment's first in the whole run).
void print_sim_run(const SimRun& r, std::size_t first_frame, std::ostream& out);

}  // namespace scw::host::pipeline
