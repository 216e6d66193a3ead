// SPDX-License-Identifier: Apache-2.0
// A rectified stereo pair whose disparities are known: textured fronto-parallel boxes in front
// of a textured background, for pipeline runs that need no camera (scw sim, tests).
#pragma once

#include <cstdint>
#include <vector>

#include <opencv2/core.hpp>

namespace scw::host::pipeline {

/// A box in the left image (pixels, inclusive-exclusive) at one disparity.
struct SyntheticBox {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  int disparity = 0;
};

struct SyntheticPair {
  cv::Mat left, right;  // CV_8UC1
  cv::Mat truth;        // CV_16S, the left image's disparity x 16
};

/// Renders the pair: each surface carries its own blurred random texture, fixed to the surface,
/// so the right image shows at x what the left shows at x + d (nearest surface first). Later
/// boxes are in front of earlier ones when they overlap and are nearer. Throws
/// std::invalid_argument for a box outside the image or a negative disparity.
SyntheticPair synthetic_pair(int width, int height, int background_disparity,
                             const std::vector<SyntheticBox>& boxes, std::uint32_t seed);

/// A street-like default for a width x height frame and a disparity range: the background at
/// dmin + 2, a pedestrian-sized box at 3/4 of the range in the middle, a car-sized box at the
/// middle of the range to the left, a narrow post near the top of the range to the right.
std::vector<SyntheticBox> street_boxes(int width, int height, int dmin, int dmax);

}  // namespace scw::host::pipeline
