// SPDX-License-Identifier: Apache-2.0
// Golden vector sets of the whole pipeline: raw left and right frames and both cameras' knots
// in; every stream between the stages (rectified left and right, disparity, what the road stage
// leaves, the object words) and the frame results out, frames back to back, at a build of the
// scw_pipeline top (docs/vectors.md, "Pipeline sets").
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

namespace scw::vectors {

/// What `scw vectors pipeline` makes a set from.
struct PipelineSetOptions {
  std::string config = "small";  // the build: "small" (the one whose top is Verilated here)
  int ppc = 1;                   // pixels per beat: 1 or 2
  int frames = 3;
  int width = 64, height = 32;  // synthetic frames' size (a pair's own size otherwise)
  std::uint32_t seed = 1;       // synthetic frames: boxes and textures
  /// Pairs of the user's (8-bit grey, one size), rectified unless `calib` is given; empty:
  /// synthetic street frames.
  std::vector<cv::Mat> left, right;
  /// A calibration (OpenCV FileStorage M1 D1 M2 D2 R T, as `scw run --calib` reads it) of the
  /// frames' size: the frames are raw and the rectifiers run its grid maps (the knots in
  /// knots.hex). Empty: the identity map.
  std::filesystem::path calib;
  bool rtl = true;  // also run the Verilated top and require its outputs to equal the C++ chain's
};

/// What write_pipeline_set() made, for the CLI to print.
struct PipelineSetSummary {
  int frames = 0, width = 0, height = 0, ppc = 0;
  std::size_t raw_beats = 0, object_words = 0;
  std::int64_t cycles = 0;  // the C++ chain's run
  bool rtl = false;         // the Verilated top's results and object table equalled the chain's
};

/// The builds write_pipeline_set() takes.
const std::vector<std::string>& pipeline_set_configs();

/// Synthetic street frames when `o` has no pairs: `o.frames` of `o.width` x `o.height`, a
/// car-sized box at the middle of the range to the left and a pedestrian-sized box that comes
/// nearer and moves right, frame by frame, appended to `o.left` and `o.right`.
void add_synthetic_frames(PipelineSetOptions& o);

/// Runs the frames through the C++ chain of the build (sim::PipelineChain, every block its C++
/// model), records every stream between the stages, checks the Verilated top against it when
/// `o.rtl`, and writes the set into `dir`: cfg.hex, knots.hex, left.hex, right.hex, rect_left.hex,
/// rect_right.hex, disparity.hex, road.hex, objects.hex, results.hex, left.png, right.png and the
/// manifest. Throws std::invalid_argument for options the build cannot take and
/// std::runtime_error when a run or a check fails (before the manifest is written).
PipelineSetSummary write_pipeline_set(const PipelineSetOptions& o, const std::filesystem::path& dir,
                                      const std::function<void(const std::string&)>& progress = {});

}  // namespace scw::vectors
