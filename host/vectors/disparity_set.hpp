// SPDX-License-Identifier: Apache-2.0
// Golden vector sets of the disparity stage: left and right pixels in, Q11.4 disparities out, from
// the C++ model checked against the direct reference (docs/vectors.md, "Disparity sets").
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "hls/disparity/disparity_params.hpp"
#include "host/disparity/run_model.hpp"

namespace scw::vectors {

/// The golden-vector build of the stage: P = 2, frames up to 128 px wide and 64 rows (the RTL's
/// row counters), 16 candidates; the window is the preset's. A replay builds scw_disparity so.
template <int N>
using DisparityVecParams = hls::disparity::DisparityParams<2, 128, N, 16, 64>;

/// The builds a set is made at: "vectors" (DisparityVecParams: P = 2, up to 128 x 64, N 5 or
/// 9, 16 candidates; the committed sets) and the pipeline's "small", "tsukuba" and "thesis"
/// (hls/pipeline/pipeline_configs.def: their size, window and candidates, at P = 1, 2 or 4).
const std::vector<std::string>& disparity_builds();

/// Pairs to match, sent back to back, and the configuration.
struct DisparityFrame {
  std::vector<cv::Mat> left, right;  // 8UC1, one size, a pair a frame
  int window = 5;                    // N: the vectors build takes 5 or 9, the others their own
  disparity::Mode mode = disparity::Mode::thesis;
  hls::disparity::DisparityConfig cfg;
  std::string description;
  cv::Mat shift;  // synthetic: the true disparity of every left pixel (8UC1), else empty
  std::string build = "vectors";
  int ppc = 2;  // the vectors build: 2
};

/// The presets `scw vectors disparity` writes: "texture" and "tsukuba".
const std::vector<std::string>& disparity_presets();
/// The pair of a preset; throws std::invalid_argument naming the presets for another name.
///   texture: 64 x 24 random texture with known shifts, N = 5, d 0..15, thesis mode.
///   tsukuba: a 96 x 48 crop of `data_dir`'s scene1.row3.col3/col4.ppm, N = 9, opencv mode
///     (throws std::runtime_error when a file is missing).
DisparityFrame disparity_preset(const std::string& name, const std::filesystem::path& data_dir);

/// Pairs of the user's, a frame each: image files (read as grey, all one size), the crop of
/// them to match (empty: the whole image), the build and the stage's settings.
struct UserPair {
  std::vector<std::filesystem::path> left, right;
  cv::Rect roi;
  int window = 9;  // the vectors build: 5 or 9; the others: their own
  disparity::Mode mode = disparity::Mode::opencv;
  int dmin = 0;
  int edge_candidates = 0;
  std::string build = "vectors";
  int ppc = 2;
};

/// The frames of a user's pairs. Throws std::invalid_argument naming what does not fit (sizes,
/// the crop, the build's frame, window and range) and std::runtime_error for a file that is not
/// an image.
DisparityFrame disparity_frames(const UserPair& pair);

/// What write_disparity_set() checked and wrote, for the CLI to print.
struct DisparitySetSummary {
  int width = 0, height = 0, ppc = 0, window = 0, dmin = 0, dmax = 0, frames = 0;
  std::string build;
  std::string mode;           // disparity::mode_name
  std::size_t beats = 0;      // output beats, each equal to the direct reference
  std::int64_t cycles = 0;    // the C++ model's run
  bool known_shifts = false;  // the frame has true disparities: the two counts below are set
  long shifts_right = 0, shifts_valid = 0;  // computed pixels that find their true disparity
};

/// Runs `f`'s frames back to back through the C++ model of its build, checks every beat against
/// the direct reference, then writes the set into `dir`: left.png, right.png (the frames stacked
/// top to bottom), left.hex, right.hex, expected.hex, expected.png and the manifest. Throws
/// std::runtime_error or std::logic_error (before writing anything) when a check fails.
DisparitySetSummary write_disparity_set(const DisparityFrame& f, const std::filesystem::path& dir);

}  // namespace scw::vectors
