// SPDX-License-Identifier: Apache-2.0
// Synthetic disparity maps with a planted road for the road stage's tests and golden vectors:
// the road, objects standing on it, noise and holes, and a configuration that can find it.
#pragma once

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include <opencv2/core.hpp>

#include "hls/road/road_params.hpp"

namespace scw::fixtures {

/// A road d(v) = slope (v - horizon) px below the horizon (nothing above it), `objects` boxes
/// standing on it (their disparity the road's at their foot row), codes jittered by up to
/// +-`noise` px, and about 1 pixel in `hole_every` invalid. CV_16UC1, disparity x 16.
struct RoadScene {
  int width = 64, height = 48;
  double slope = 0.45, horizon = 12.0;
  double noise = 0.2;
  int hole_every = 9;
  int objects = 2;
};

inline cv::Mat road_map(const RoadScene& s, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> jitter(-s.noise, s.noise);
  std::uniform_int_distribution<int> hole(0, s.hole_every - 1);
  cv::Mat m(s.height, s.width, CV_16UC1, cv::Scalar(0));
  for (int v = 0; v < s.height; ++v)
    for (int u = 0; u < s.width; ++u) {
      const double d = s.slope * (v - s.horizon);
      if (d < 0.5 || hole(rng) == 0) continue;
      m.at<std::uint16_t>(v, u) = static_cast<std::uint16_t>(std::lround((d + jitter(rng)) * 16));
    }
  std::uniform_int_distribution<int> col(0, s.width - 8);
  std::uniform_int_distribution<int> foot(static_cast<int>(s.horizon) + 8, s.height - 1);
  for (int k = 0; k < s.objects; ++k) {
    const int u0 = col(rng), v1 = foot(rng), h = std::max(4, (v1 - static_cast<int>(s.horizon)) / 2);
    const double d = s.slope * (v1 - s.horizon);
    const auto code = static_cast<std::uint16_t>(std::lround(d * 16));
    for (int v = std::max(0, v1 - h); v <= v1; ++v)
      for (int u = u0; u < std::min(s.width, u0 + 6); ++u) m.at<std::uint16_t>(v, u) = code;
  }
  return m;
}

/// A configuration whose nominal road is `slope` x `slope_error` from row `horizon` + `shift`,
/// plausible for slopes within half to twice `slope` and horizons within +-8 rows.
inline hls::road::RoadConfig road_config(const RoadScene& s, double slope_error, double shift,
                                         std::uint32_t min_count = 50) {
  const double unit = hls::road::kPxUnit;
  hls::road::RoadConfig c;
  const double a = s.slope * slope_error;
  c.nominal.a = static_cast<std::int32_t>(std::lround(a * unit));
  c.nominal.b = static_cast<std::int32_t>(std::lround(-a * (s.horizon + shift) * unit));
  c.a_min = static_cast<std::int32_t>(std::lround(s.slope / 2 * unit));
  c.a_max = static_cast<std::int32_t>(std::lround(s.slope * 2 * unit));
  c.h_min = static_cast<std::uint16_t>(std::max(0.0, s.horizon - 8));
  c.h_max = static_cast<std::uint16_t>(s.horizon + 8);
  c.min_count = min_count;
  return c;
}

}  // namespace scw::fixtures
