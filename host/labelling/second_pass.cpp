// SPDX-License-Identifier: Apache-2.0
// number_objects(): the label image from the model's node map and roots.
#include "host/labelling/second_pass.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <unordered_map>

namespace scw::labelling {

std::vector<hls::labelling::Object> raster_sorted(std::vector<hls::labelling::Object> objects) {
  std::sort(objects.begin(), objects.end(), raster_before);
  return objects;
}

Numbering number_objects(const std::vector<hls::labelling::Object>& objects,
                         const std::vector<std::int32_t>& node_map, int width, int height,
                         const std::function<int(int)>& root_of) {
  std::vector<std::size_t> order(objects.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return raster_before(objects[a], objects[b]);
  });
  Numbering n;
  n.label_of.assign(objects.size(), 0);
  std::unordered_map<int, std::uint16_t> label_of_root;
  for (std::size_t r = 0; r < order.size(); ++r) {
    const auto& o = objects[order[r]];
    const int node1 = node_map[static_cast<std::size_t>(o.first_y) * width + o.first_x];
    if (node1 == 0) throw std::logic_error("labelling: an object's first pixel has no node");
    const auto label = static_cast<std::uint16_t>(std::min<std::size_t>(r + 1, 65535));
    label_of_root[root_of(node1 - 1)] = label;
    n.label_of[order[r]] = label;
  }
  n.labels = cv::Mat::zeros(height, width, CV_16UC1);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const int node1 = node_map[static_cast<std::size_t>(y) * width + x];
      if (node1 == 0) continue;
      const auto it = label_of_root.find(root_of(node1 - 1));
      if (it != label_of_root.end()) n.labels.at<std::uint16_t>(y, x) = it->second;
    }
  return n;
}

}  // namespace scw::labelling
