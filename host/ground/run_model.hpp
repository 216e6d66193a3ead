// SPDX-License-Identifier: Apache-2.0
// Runs the streaming ground-removal model over a whole disparity map (no stalls): what the CLI
// and the real-data checks use.
#pragma once

#include <cstdint>
#include <opencv2/core.hpp>

#include "hls/ground/ground_params.hpp"

namespace scw::ground {

using hls::ground::GroundConfig;

/// The host's build of the stage: rows up to 2048 pixels (the other stages' host width); the
/// height is unbounded.
constexpr int kHostMaxWidthPx = 2048;

/// Ground removal of one disparity map through the streaming model (hls::ground clocked by
/// sim::GroundModel, one beat per clock, output always taken). `d16` is CV_16SC1, disparity x 16
/// (Q11.4) with invalid 0 or negative, as scw::disparity::disparity_image returns it, or
/// CV_16UC1 holding the same bit patterns (the labelling stage's input); the result has the
/// same type and size, ground pixels 0, pixel for pixel equal to reference::ground_reference.
/// `cycles`, if given, receives the clocks the frame took. Throws std::invalid_argument, saying
/// what is supported, for an empty map, another type, a width above kHostMaxWidthPx or a
/// configuration field outside 0 .. 32767; std::logic_error if the model stops or flags an error.
cv::Mat remove_ground(const cv::Mat& d16, const GroundConfig& cfg, std::int64_t* cycles = nullptr);

}  // namespace scw::ground
