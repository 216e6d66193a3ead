// SPDX-License-Identifier: Apache-2.0
// `scw run`'s camera and warning options (run_options.hpp).
#include "host/cli/run_options.hpp"

#include <string>

#include "host/cli/value_checks.hpp"

namespace scw::cli {

void add_camera_options(CLI::App* cmd, app::CameraInput& camera) {
  cmd->add_option("--calib", camera.calib,
                  "OpenCV FileStorage calibration (M1 D1 M2 D2 R T) of raw pairs");
  cmd->add_flag("--rectified", camera.rectified,
                "The pairs are already rectified: skip rectification");
  cmd->add_option("--focal", camera.focal, "With --rectified: focal length, px");
  cmd->add_option("--baseline", camera.baseline, "With --rectified: baseline, m");
  cmd->add_option("--cx", camera.cx,
                  "With --rectified: principal point u, px (default: image centre)")
      ->check(non_negative("px", "319.5"));
  cmd->add_option("--cy", camera.cy,
                  "With --rectified: principal point v, px (default: image centre)")
      ->check(non_negative("px", "239.5"));
  cmd->add_option("--calib-unit-m", camera.calib_unit_m,
                  "Metres per calibration unit (e.g. the chessboard square), default 1")
      ->capture_default_str();
  cmd->add_option("--maps", camera.maps,
                  "Raw pairs on --engine cpp: full (the calibration's maps, quantised) or grid "
                  "(knots every 2^--grid-log2 px, expanded as the RTL's map-grid stage does; "
                  "--engine rtl always runs grid knots at its build's spacing)")
      ->capture_default_str()
      ->check(CLI::IsMember({"full", "grid"}));
  cmd->add_option("--grid-log2", camera.grid_log2,
                  "Knot spacing of --maps grid, log2 px (4: the thesis build's 16 px)")
      ->capture_default_str()
      ->check(CLI::Range(2, 7));
}

void add_warning_options(CLI::App* cmd, host::warning::WarningSetup& warning) {
  cmd->add_option("--min-height", warning.min_height_m,
                  "Lower objects are not obstacles (road markings), m")
      ->capture_default_str()
      ->check(non_negative("m", "0.5"));
  cmd->add_option_function<std::string>(
         "--distance-rule",
         [&warning](const std::string& rule) {
           warning.distance_rule = rule == "closest" ? hls::warning::DistanceRule::kClosest
                                                     : hls::warning::DistanceRule::kSpread;
         },
         "Which disparity places an object: spread, min(d_max, mean + k sd) of its disparities "
         "(default), or closest, its largest (the thesis's)")
      ->check(CLI::IsMember({"spread", "closest"}));
  cmd->add_option("--spread-k", warning.spread_k,
                  "k of the spread rule, 0 .. 15.9375 (steps of 1/16)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 15.9375));
  cmd->add_option("--near", warning.near_m, "Outside the tunnel: medium when this close to it, m")
      ->capture_default_str()
      ->check(non_negative("m", "1"));
  cmd->add_option("--car-width", warning.car_width_m, "Car width, m (tunnel: 1.5x)")
      ->capture_default_str()
      ->check(positive("m", "1.8"));
  cmd->add_option("--car-height", warning.car_height_m, "Car height, m (tunnel: 1.5x)")
      ->capture_default_str()
      ->check(positive("m", "1.5"));
}

}  // namespace scw::cli
