// SPDX-License-Identifier: Apache-2.0
// Runs the streaming labelling model over a whole disparity map (no stalls) and its second
// pass: what the CLI, the golden vectors and the real-data checks use.
#pragma once

#include <cstdint>
#include <opencv2/core.hpp>
#include <string>
#include <utility>
#include <vector>

#include "hls/labelling/labelling_params.hpp"

namespace scw::labelling {

using hls::labelling::FrameStatus;
using hls::labelling::LabellingConfig;
using hls::labelling::Object;

/// The host's build of the stage: frames up to 2048 x 1024, up to 8 x 8 tiles of 2048 labels,
/// 4096 objects per frame.
constexpr int kHostMaxWidthPx = 2048;
constexpr int kHostMaxHeight = 1024;
constexpr int kHostMaxTiles = 8;
constexpr int kHostLabelsPerTile = 2048;
constexpr int kHostMaxObjects = 4096;

/// One frame through the model.
struct Segmentation {
  std::vector<Object> objects;  // as the stage emits them (ascending root node)
  FrameStatus status;
  /// CV_16UC1: 0 = no object, else the object's number, 1.. in raster order of its first
  /// pixel (the model's second pass); objects below min_area are 0.
  cv::Mat labels;
  /// `objects` renumbered: objects_by_label[k - 1] is the object labelled k.
  std::vector<Object> objects_by_label;
  std::int64_t cycles = 0;  // clock cycles the frame took, reset to status word
};

/// A tile grid given as "CxR" (tile columns x tile rows, such as 4x2): {C, R}. Throws
/// std::runtime_error quoting `text` and the form when it is not one.
std::pair<int, int> parse_tiles(const std::string& text);

/// Tiles of ceil(width / tiles_x) x ceil(height / tiles_y) pixels for a grid of at most
/// tiles_x x tiles_y tiles.
LabellingConfig grid_config(int width, int height, int tiles_x, int tiles_y, int floor,
                            int min_area);

/// Labels a CV_16UC1 map of Q11.4 disparities (disparity x 16) with the streaming model at the
/// host's capacities. Throws std::invalid_argument saying what is wrong and what is supported
/// for: an empty or non-16-bit map, a size above the host's build, a tile grid above 16 x 16 or
/// a config that does not match the map.
Segmentation segment(const cv::Mat& disp_q4, const LabellingConfig& cfg);

}  // namespace scw::labelling
