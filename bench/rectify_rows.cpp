// SPDX-License-Identifier: Apache-2.0
// How many raw rows on chip a calibration needs, and how wide its knots are: the bundled
// chessboard calibration and KITTI-like automotive rigs at the thesis size (1280 x 480), with
// both the full maps and the grid maps (G = 16) the top's expanders stream. See docs/rectify.md,
// "How many raw rows".
//
// For every case it prints the row window of each camera's map (raw rows v + dy_min ..
// v + dy_max carry weight for output row v), the lead D and the rows needed (D + 2 - dy_min,
// hls::rectify::in_row_window), and the range of the knots in pixels against the image.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <opencv2/calib3d.hpp>
#include <opencv2/core.hpp>

#include "host/rectify/calibration.hpp"
#include "host/rectify/fixed_map.hpp"
#include "host/rectify/map_grid.hpp"

namespace {

using namespace scw::rectify;

/// A KITTI-like stereo rig at 1280 x 480: f px, principal point (640, cy), radial k1, k2, k3
/// (tangential terms 0), the right camera turned by yaw / pitch / roll degrees against the
/// left one, baseline 0.54 m.
StereoCalibration rig(double f, double cy, double k1, double k2, double k3, double yaw_deg,
                      double pitch_deg, double roll_deg) {
  StereoCalibration c;
  c.image_size = cv::Size(1280, 480);
  c.M1 = (cv::Mat_<double>(3, 3) << f, 0, 640, 0, f, cy, 0, 0, 1);
  c.M2 = c.M1.clone();
  c.D1 = (cv::Mat_<double>(1, 5) << k1, k2, 0, 0, k3);
  c.D2 = c.D1.clone();
  const double d = CV_PI / 180.0;
  cv::Mat rv = (cv::Mat_<double>(3, 1) << pitch_deg * d, yaw_deg * d, roll_deg * d);
  cv::Rodrigues(rv, c.R);
  c.T = (cv::Mat_<double>(3, 1) << -0.54, 0, 0);
  c.source = "rig";
  return c;
}

struct Range {
  double lo = 1e30, hi = -1e30;
  void note(double v) {
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
};

void report(const std::string& name, const StereoCalibration& calib, double alpha) {
  const auto rect = rectify_calibration(calib, alpha);
  const FixedMap l = quantise_map(rect.map1_x, rect.map1_y);
  const FixedMap r = quantise_map(rect.map2_x, rect.map2_y);
  const RowWindow wl = row_window(l), wr = row_window(r);
  const RectifyPlan full = plan_rows({wl, wr});
  const auto knots = grid_knots(calib, rect, 4);
  const FixedMap gl = expand(knots.left), gr = expand(knots.right);
  const RowWindow gwl = row_window(gl), gwr = row_window(gr);
  const RectifyPlan grid = plan_rows({gwl, gwr});
  Range kx, ky, dx, dy;  // knots, and knots minus their grid position (i G, j G)
  int clamped = 0;
  for (const auto* g : {&knots.left, &knots.right}) {
    clamped += g->clamped;
    const double s = 1.0 / (1 << g->knot_frac_bits);
    for (int j = 0; j < g->rows; ++j)
      for (int i = 0; i < g->cols; ++i) {
        const auto& k = g->at(i, j);
        kx.note(k.x * s);
        ky.note(k.y * s);
        dx.note(k.x * s - i * g->grid());
        dy.note(k.y * s - j * g->grid());
      }
  }
  std::printf(
      "%-34s alpha %5.2f f %6.1f | full: L v%+d..v%+d R v%+d..v%+d D %d rows %d | grid16: D %d "
      "rows %d | knots x %.0f..%.0f y %.0f..%.0f, minus (iG, jG) x %.0f..%.0f y %.0f..%.0f "
      "(%dx%d)%s\n",
      name.c_str(), alpha, rect.focal_px(), wl.dy_min, wl.dy_max, wr.dy_min, wr.dy_max,
      full.lead_rows, full.rows_needed, grid.lead_rows, grid.rows_needed, kx.lo, kx.hi, ky.lo,
      ky.hi, dx.lo, dx.hi, dy.lo, dy.hi, calib.image_size.width, calib.image_size.height,
      clamped ? (" CLAMPED " + std::to_string(clamped)).c_str() : "");
}

}  // namespace

int main() {
  const std::string chess =
      std::string(SCW_DATA_DIR) + "/chessboard/derived_stereo_calibration_helper.yml";
  const auto cb = load_stereo_calibration(chess);
  for (double a : {-1.0, 0.0, 0.25, 0.5, 1.0}) report("chessboard 640x480", cb, a);

  // KITTI's colour cameras (1392 x 512 raw, f about 960 px, k1 about -0.37, k2 0.2, k3 -0.07)
  // scaled to 1280 x 480: f 880; a 1.5 degree relative yaw and 1 degree pitch between the two.
  for (double a : {-1.0, 0.0, 0.5})
    report("kitti-like f880 k1-.37", rig(880, 210, -0.37, 0.20, -0.07, 1.5, 1.0, 0.2), a);
  // The same rig with milder lenses and a better aligned pair.
  for (double k1 : {0.0, -0.1, -0.2, -0.3})
    report("rig f880 k1 " + std::to_string(k1).substr(0, 5) + " pitch .5",
           rig(880, 240, k1, 0.0, 0.0, 1.0, 0.5, 0.1), -1.0);
  // Misalignment alone (no distortion): pitch and roll move rows, yaw does not.
  for (double pitch : {0.5, 1.0, 2.0})
    for (double roll : {0.0, 1.0})
      report("rig f880 pitch " + std::to_string(pitch).substr(0, 3) + " roll " +
                 std::to_string(roll).substr(0, 3),
             rig(880, 240, 0.0, 0.0, 0.0, 1.0, pitch, roll), -1.0);
  // A wide automotive lens (HFOV about 100 deg at 1280 px) with strong barrel distortion.
  for (double a : {-1.0, 0.0})
    report("wide f540 k1-.30 k2 .08", rig(540, 240, -0.30, 0.08, -0.01, 1.0, 0.5, 0.2), a);
  return 0;
}
