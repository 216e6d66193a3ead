// SPDX-License-Identifier: Apache-2.0
// The golden vector set `scw stream` writes: one frame through the line buffer, each beat in and
// each beat out with the rows above, replayable in any simulator with $readmemh.
#pragma once

#include <filesystem>
#include <vector>

#include <opencv2/core.hpp>

#include "sim/words/pack.hpp"

namespace scw::vectors {

/// The line buffer's build and the frame's size, as the set's config records them.
struct LineBufferSetConfig {
  int ppc = 1, max_width_px = 0, rows = 0, latency = 0;
};

/// Writes `dir`: input.png (`grey`), input.hex (`input`, pixel beats of ppc pixels) and
/// expected.hex (`expected`, beats of ppc x rows pixels), and the manifest.
void write_line_buffer_set(const std::filesystem::path& dir, const LineBufferSetConfig& c,
                           const cv::Mat& grey, const std::vector<sim::Bits>& input,
                           const std::vector<sim::Bits>& expected);

}  // namespace scw::vectors
