// SPDX-License-Identifier: Apache-2.0
// The camera `scw run` works with: from a calibration of raw pairs (rectified focal length,
// principal point, baseline, and the rectification maps), or given for pairs already rectified.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include <opencv2/core.hpp>

#include "host/app/run.hpp"
#include "host/rectify/map_grid.hpp"

namespace scw::app {

/// Where the camera comes from (the `scw run` options).
struct CameraInput {
  std::string calib;       // OpenCV FileStorage calibration of raw pairs
  bool rectified = false;  // the pairs are rectified: focal and baseline given instead
  double focal = 0, baseline = 0;  // px, m; 0 = not given
  double cx = -1, cy = -1;         // px; negative: the image centre
  double calib_unit_m = 1.0;       // metres per calibration unit
  std::string maps = "full";       // raw pairs: full quantised maps, or expanded grid knots
  int grid_log2 = 4;               // knot spacing of maps == "grid"
};

/// How the pairs are rectified: the host's fixed-point maps for the C++ models, and the grid
/// knots at a spacing of 2^grid_log2 for the Verilated rectifiers. Both empty for pairs already
/// rectified.
struct Rectification {
  std::optional<RectifyMaps> maps;
  std::function<rectify::StereoKnots(int grid_log2)> knots;
};

/// Sets `w`'s focal length, baseline and principal point from `in` for images of `size`, and
/// builds the maps and knot source of a calibration. Throws std::runtime_error saying what is
/// missing or wrong (no calibration, a non-positive focal length or baseline, a calibration
/// made for another image size, maps the host stage cannot serve).
Rectification set_up_camera(const CameraInput& in, cv::Size size, host::warning::WarningSetup& w);

}  // namespace scw::app
