// SPDX-License-Identifier: Apache-2.0
// The labelling model's second pass: the label image from each pixel's node and the nodes'
// roots, objects numbered in raster order of their first pixel.
#pragma once

#include <cstdint>
#include <functional>
#include <opencv2/core.hpp>
#include <vector>

#include "hls/labelling/labelling_params.hpp"

namespace scw::labelling {

/// Raster order of the objects' first pixels: the order objects are numbered in.
inline bool raster_before(const hls::labelling::Object& a, const hls::labelling::Object& b) {
  return a.first_y != b.first_y ? a.first_y < b.first_y : a.first_x < b.first_x;
}

/// `objects` sorted by raster_before.
std::vector<hls::labelling::Object> raster_sorted(std::vector<hls::labelling::Object> objects);

/// The label image of one frame and each object's number.
struct Numbering {
  cv::Mat labels;                        // CV_16UC1: 0 = no object, else 1.. in raster order
  std::vector<std::uint16_t> label_of;  // label_of[i]: the number of objects[i]
};

/// Numbers the objects a frame emitted (in any order) 1.. in raster order of their first pixel
/// and labels every pixel with its object's number. `node_map` holds each pixel's node + 1
/// (0 = none, hls::labelling::Labelling::set_node_map) and `root_of(node)` the node's root after
/// Resolve; an object is found through its first pixel's root, so pixels of unreported roots
/// (below min_area, past MaxObjects) stay 0. Throws std::logic_error if an object's first pixel
/// has no node.
Numbering number_objects(const std::vector<hls::labelling::Object>& objects,
                         const std::vector<std::int32_t>& node_map, int width, int height,
                         const std::function<int(int)>& root_of);

}  // namespace scw::labelling
