// SPDX-License-Identifier: Apache-2.0
// Runs the HLS rectify kernel over whole images (no sim/, no stalls): what the CLI and the
// real-data checks use to get "our" rectified picture.
#pragma once

#include <memory>
#include <opencv2/core.hpp>

#include "host/rectify/fixed_map.hpp"

namespace scw::rectify {

/// Rectifies one 8-bit grey image with the fixed-point streaming model (the CLI's built
/// stage: P = 1, up to 2048 x 2048, kHostStageRows raw rows). Throws MapNotServable if the map
/// needs more rows, std::invalid_argument if sizes disagree.
constexpr int kHostStageRows = 128;
cv::Mat rectify_image(const cv::Mat& raw, const FixedMap& map, int lead_rows);

/// rectify_image for a sequence: the map is checked and turned into beats once, and one stage
/// takes the frames back to back, as the pipeline's does (a frame reads only rows of its own, so
/// each output equals rectify_image's).
class Rectifier {
 public:
  Rectifier(const FixedMap& map, int lead_rows);
  ~Rectifier();
  Rectifier(Rectifier&&) noexcept;
  Rectifier& operator=(Rectifier&&) noexcept;
  cv::Mat operator()(const cv::Mat& raw);

 private:
  struct Stage;
  std::unique_ptr<Stage> stage_;
};

}  // namespace scw::rectify
