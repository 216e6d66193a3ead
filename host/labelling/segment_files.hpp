// SPDX-License-Identifier: Apache-2.0
// What `scw segment` reads and writes: a disparity map as the labelling stage takes it (16-bit
// Q11.4 or 8-bit disparity x S), the object table and the post-processed regions as CSV.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "hls/labelling/labelling_params.hpp"
#include "host/labelling/postprocess.hpp"

namespace scw::labelling {

using hls::labelling::FrameStatus;
using hls::labelling::Object;

/// A disparity map as the stage takes it, and how it was read.
struct DisparityInput {
  cv::Mat q4;  // CV_16UC1, Q11.4
  std::string kind;
  long negatives = 0;  // 16-bit values with the int16 sign bit set, read as no data
};

/// Reads `path`: a 16-bit PNG of disparity x 16 (Q11.4; negative codes are no data) or an 8-bit
/// image of disparity x `scale` (`scale_given` says whether the user gave it: a 16-bit map
/// refuses it). Throws std::runtime_error saying what the file is and what is read.
DisparityInput read_disparity_map(const std::string& path, double scale, bool scale_given);

/// A Q11.4 value as disparity in pixels, exactly (at most 4 decimals).
std::string px_text(int q4);

/// "ok", or the status flags that are set ("tile_overflow object_overflow stream_error").
std::string status_flags(const FrameStatus& s);

/// One row per object (label k is objects[k - 1]): box, disparities, moments, Hu invariants.
void write_objects_csv(const std::filesystem::path& p, const std::vector<Object>& objects);
/// One row per region: its labels, box, disparities, hull and visible pixels.
void write_regions_csv(const std::filesystem::path& p, const std::vector<Region>& regions);

}  // namespace scw::labelling
