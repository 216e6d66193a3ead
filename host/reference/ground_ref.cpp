// SPDX-License-Identifier: Apache-2.0
// ground_reference(): the ground rule pixel by pixel; default_ground_config(): limits from b / h.
#include "host/reference/ground_ref.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace scw::reference {

cv::Mat ground_reference(const cv::Mat& d16, const hls::ground::GroundConfig& cfg) {
  if (d16.empty() || (d16.type() != CV_16SC1 && d16.type() != CV_16UC1))
    throw std::invalid_argument(
        "ground_reference: the map must be one 16-bit channel of disparity x 16");
  cv::Mat out = d16.clone();
  if (!cfg.enable) return out;
  // Read every value as int16 (invalid = 0 or negative), whatever the Mat's signedness.
  auto at = [&d16](int x, int y) {
    return static_cast<int>(static_cast<std::int16_t>(d16.at<std::uint16_t>(y, x)));
  };
  constexpr int kAbove = 10;
  for (int y = kAbove; y < d16.rows; ++y) {
    for (int x = 0; x < d16.cols; ++x) {
      int g[kAbove + 1];
      bool ground = true;
      for (int j = 0; j <= kAbove; ++j) {
        g[j] = at(x, y - kAbove + j);
        if (g[j] <= 0) ground = false;
      }
      for (int j = 0; j < kAbove && ground; ++j)
        if (g[j + 1] - g[j] < -cfg.step_tol_q4) ground = false;
      const int rise = g[kAbove] - g[0];
      if (ground && rise >= cfg.min_rise_q4 && rise <= cfg.max_rise_q4)
        out.at<std::uint16_t>(y, x) = 0;
    }
  }
  return out;
}

}  // namespace scw::reference

namespace scw::ground {

GroundConfig default_ground_config(double baseline_m, double camera_height_m) {
  if (!(std::isfinite(baseline_m) && baseline_m > 0.0))
    throw std::invalid_argument("ground: the baseline must be a positive number of metres, not " +
                                std::to_string(baseline_m));
  if (!(std::isfinite(camera_height_m) && camera_height_m > 0.0))
    throw std::invalid_argument(
        "ground: the camera height above the road must be a positive number of metres, not " +
        std::to_string(camera_height_m));
  const double rise_q4 = 10.0 * 16.0 * baseline_m / camera_height_m;  // 10 rows of b / h px
  const double max_q4 = std::round(2.0 * rise_q4);
  if (max_q4 > hls::ground::kMaxQ4)
    throw std::invalid_argument(
        "ground: baseline / camera height = " + std::to_string(baseline_m / camera_height_m) +
        " px per row needs a rise limit above 2047.9375 px");
  GroundConfig c;
  c.enable = true;
  c.step_tol_q4 = 4;  // 0.25 px
  c.min_rise_q4 = std::max(1, static_cast<int>(std::round(0.5 * rise_q4)));
  c.max_rise_q4 = static_cast<int>(max_q4);
  return c;
}

}  // namespace scw::ground
