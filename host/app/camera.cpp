// SPDX-License-Identifier: Apache-2.0
// set_up_camera() (host/app/camera.hpp).
#include "host/app/camera.hpp"

#include <sstream>
#include <stdexcept>

#include "host/rectify/calibration.hpp"
#include "host/rectify/fixed_map.hpp"
#include "host/rectify/run_model.hpp"

namespace scw::app {
namespace {

/// Zero is the options' "not given"; any other value must be a positive length.
void need_positive(double v, const std::string& opt, const std::string& what,
                   const std::string& unit, const std::string& eg) {
  if (v == 0)
    throw std::runtime_error("--rectified needs " + opt + " (" + what + ", " + unit + "), e.g. " +
                             opt + " " + eg);
  if (!(v > 0)) {
    std::ostringstream m;
    m << opt << " " << v << ": the " << what << " must be a positive number of " << unit
      << ", e.g. " << opt << " " << eg;
    throw std::runtime_error(m.str());
  }
}

}  // namespace

Rectification set_up_camera(const CameraInput& in, cv::Size size, host::warning::WarningSetup& w) {
  if (in.rectified) {
    need_positive(in.focal, "--focal", "focal length", "px", "615");
    need_positive(in.baseline, "--baseline", "baseline", "m", "0.1");
    w.focal_px = in.focal;
    w.baseline_m = in.baseline;
    w.cu_px = in.cx >= 0 ? in.cx : (size.width - 1) / 2.0;
    w.cv_px = in.cy >= 0 ? in.cy : (size.height - 1) / 2.0;
    return {};
  }
  if (in.calib.empty())
    throw std::runtime_error("give --calib CALIB for raw pairs, or --rectified with --focal, "
                             "--baseline (and --cx, --cy) for pairs already rectified");
  const auto calib = rectify::load_stereo_calibration(in.calib, size);
  if (calib.image_size != size)
    throw std::runtime_error("the images are " + std::to_string(size.width) + " x " +
                             std::to_string(size.height) + " px but the calibration '" + in.calib +
                             "' is for " + std::to_string(calib.image_size.width) + " x " +
                             std::to_string(calib.image_size.height) + " px");
  const auto rect = rectify::rectify_calibration(calib);
  w.focal_px = rect.focal_px();
  w.baseline_m = rect.baseline() * in.calib_unit_m;
  w.cu_px = rect.principal_point().x;
  w.cv_px = rect.principal_point().y;
  RectifyMaps maps;
  if (in.maps == "grid") {  // what the RTL's map-grid expanders stream (docs/rectify.md)
    const auto knots = rectify::grid_knots(calib, rect, in.grid_log2);
    maps.left = rectify::expand(knots.left);
    maps.right = rectify::expand(knots.right);
  } else {
    maps.left = rectify::quantise_map(rect.map1_x, rect.map1_y);
    maps.right = rectify::quantise_map(rect.map2_x, rect.map2_y);
  }
  const auto plan = rectify::plan_for_stage(
      {rectify::row_window(maps.left), rectify::row_window(maps.right)}, rectify::kHostStageRows,
      in.calib);
  maps.lead_rows = plan.lead_rows;
  return {maps,
          [calib, rect](int grid_log2) { return rectify::grid_knots(calib, rect, grid_log2); }};
}

}  // namespace scw::app
