// SPDX-License-Identifier: Apache-2.0
// What `scw disparity` reads and writes: a rectified pair from files through the disparity
// model, and the 8-bit, 16-bit and colour pictures of its map.
#pragma once

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "host/disparity/run_model.hpp"

namespace scw::disparity {

/// What a run is asked for (the `scw disparity` options).
struct FilesOptions {
  std::string left, right;
  int window = 0;
  int min_disp = 0, max_disp = 0;
  std::string mode = mode_name(kDefaultMode);
  int prefilter_cap = -1, texture = -1, uniqueness = -1, sad_limit = -1;  // -1: the mode's
  int edge_candidates = 0;   // DisparityConfig::edge_candidates
  std::string out;           // 8-bit picture, always written
  std::string out16, color;  // empty: not written
};

/// What a run computed and wrote.
struct FilesRun {
  cv::Mat d16;                       // CV_16S, disparity x 16 (Q11.4)
  std::int16_t invalid = 0;          // the code of a pixel without a disparity
  long invalid_pixels = 0;           // pixels holding it (in thesis mode with min 0 also d = 0)
  std::vector<std::string> written;  // the files, in the order written
};

/// Reads the pair as grey, runs disparity_image with the mode's configuration and the options'
/// overrides, and writes the pictures (creating their folders). The settings go to `log` before
/// the run. Throws std::runtime_error naming both files when they differ in size, and what
/// disparity_image and host::io throw otherwise.
FilesRun run_disparity_files(const FilesOptions& o, std::ostream& log);

/// 0 = invalid, else the integer disparity (x16 value >> 4) saturated to 0 .. 255 (a valid d
/// < 1 also reads 0: docs/disparity.md).
cv::Mat disparity_8bit(const cv::Mat& d16, std::int16_t invalid);

/// cv::COLORMAP_JET over dmin .. dmax (x16 values, so sub-pixel steps show), invalid black.
cv::Mat disparity_colour(const cv::Mat& d16, std::int16_t invalid, int dmin, int dmax);

}  // namespace scw::disparity
