// SPDX-License-Identifier: Apache-2.0
// The road stage's configuration from the rig in metres and pixels, and its defaults.
#pragma once

#include "hls/road/road_params.hpp"

namespace scw::road {

using hls::road::RoadConfig;

/// What the road stage needs to know about the camera and the rule, in physical units
/// (docs/road.md, "Defaults": chosen on the seed-1 street scenes, reported on seed 2).
struct RoadSetup {
  double baseline_m = 0.54;
  double camera_height_m = 1.20;  // nominal: frame 0's road, and the plausible range about it
  double camera_pitch_deg = 0.0;  // nominal: the camera's downward pitch, frame 0's horizon
  double cv_px = 0.0;             // the rectified principal point's row
  double focal_px = 0.0;
  double height_ratio = 2.0;      // a fitted road is plausible for a camera height within
                                  //   nominal / ratio .. nominal x ratio
  double max_pitch_deg = 3.0;     //   and a horizon within this pitch of the principal point
  double tol_px = 1.0, tol_rel = 0.15;    // road pixel: |d - d_road| <= tol + tol_rel d_road
  double gate_px = 4.0, gate_rel = 0.15;  // the fit takes pixels within gate + gate_rel d_road
  int min_count = 2000;                   // pixels a fit needs
  bool enable = true;
};

/// The defaults for a rig: its baseline, focal length and principal point row, the camera's
/// nominal height and downward pitch (degrees).
RoadSetup rig_setup(double baseline_m, double focal_px, double cv_px, double camera_height_m,
                    double camera_pitch_deg = 0.0);

/// The fixed-point configuration; throws std::invalid_argument naming a value that is not
/// positive or does not fit the ports.
RoadConfig to_fixed(const RoadSetup& s);

}  // namespace scw::road
