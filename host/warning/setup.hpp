// SPDX-License-Identifier: Apache-2.0
// The warning stage's parameters in metres and pixels, their defaults, and their fixed-point
// form for the stage (docs/warning.md).
#pragma once

#include <Eigen/Core>

#include "hls/warning/warning_params.hpp"

namespace scw::host::warning {

/// Camera, car and thresholds. Defaults: the thesis's vehicle geometry (Fig. 5.4) and eq. 5.2;
/// the camera is the Karlsruhe pair's assumed rig (f about 700 px, b 0.54 m).
struct WarningSetup {
  double focal_px = 700.0;
  double baseline_m = 0.54;
  double cu_px = 0.0, cv_px = 0.0;  // principal point of the rectified left image
  /// The vehicle origin (front bumper centre, on the ground) in camera coordinates, m:
  /// x right, y up, z ahead. Thesis: T = (-0.30, -1.20, 1.65).
  Eigen::Vector3d vehicle_origin{-0.30, -1.20, 1.65};
  double car_width_m = 1.80;   // not given in the thesis: a mid-size car
  double car_height_m = 1.50;
  double tunnel_scale = 1.5;   // the tunnel is 50 % wider and higher than the car (5.4)
  double high_m = 10.0;        // eq. 5.2
  double medium_m = 20.0;
  double near_m = 1.0;         // outside the tunnel: medium when this close to it (and < medium)
  double min_height_m = 0.5;   // lower objects (road markings) are not obstacles
  double d_limit_px = 64.0;    // the top of the disparity search range: objects reaching it are
                               // closer than the pipeline measures
  /// Which disparity places an object (docs/warning.md "The distance rule"): the thesis's
  /// largest (kClosest) or min(d_max, mean + spread_k sd) of the object's disparities (kSpread,
  /// the default: k chosen on cyclist-crossing and pedestrian-running, docs/scene.md).
  hls::warning::DistanceRule distance_rule = hls::warning::DistanceRule::kSpread;
  double spread_k = 0.75;      // k, 0 .. 15.9375 in steps of 1/16

  double tunnel_half_width_m() const { return 0.5 * tunnel_scale * car_width_m; }
  double tunnel_height_m() const { return tunnel_scale * car_height_m; }
};

/// The stage's configuration: every value rounded to its port's format. Throws
/// std::invalid_argument naming the value that does not fit.
hls::warning::WarningConfig to_fixed(const WarningSetup& s);

}  // namespace scw::host::warning
