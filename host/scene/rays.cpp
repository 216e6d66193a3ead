// SPDX-License-Identifier: Apache-2.0
// Sub-sample ray tables (host/scene/rays.hpp).
#include "host/scene/rays.hpp"

#include <opencv2/calib3d.hpp>
#include <opencv2/core/utility.hpp>
#include <stdexcept>
#include <string>

namespace scw::host::scene {

double subsample_offset(int k, int n) { return (k + 0.5) / n - 0.5; }

std::vector<cv::Point2d> undistort(const CameraModel& cam, const std::vector<cv::Point2d>& uv) {
  std::vector<cv::Point2d> xy;
  if (uv.empty()) return xy;
  cv::undistortPoints(uv, xy, cam.matrix(), cam.dist, cv::noArray(), cv::noArray(),
                      cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 20, 1e-12));
  return xy;
}

cv::Vec3d ray_direction(const StereoRig& rig, Side side, cv::Point2d uv) {
  const cv::Point2d p = undistort(rig.camera(side), {uv}).front();
  return rig.camera_to_vehicle(side) * cv::Vec3d(p.x, p.y, 1.0);
}

RayTable::RayTable(const StereoRig& rig, Side side, int subsamples)
    : n_(subsamples),
      size_(rig.image_size),
      focal_px_(rig.camera(side).fx),
      origin_(rig.centre_in_vehicle(side)),
      to_vehicle_(rig.camera_to_vehicle(side)) {
  if (n_ < 1 || n_ > 8)
    throw std::invalid_argument("ray table: " + std::to_string(n_) +
                                " sub-samples per axis; give 1 .. 8");
  xy_.create(size_.height * n_, size_.width * n_, CV_32FC2);
  // One sample row at a time, the rows on OpenCV's threads (a point's undistortion depends on it
  // alone, so the table is the same with any number of threads); the double-precision scratch
  // stays small.
  cv::parallel_for_(cv::Range(0, xy_.rows), [&](const cv::Range& rows) {
    std::vector<cv::Point2d> uv(static_cast<std::size_t>(xy_.cols));
    for (int sy = rows.start; sy < rows.end; ++sy) {
      const double v = sy / n_ + subsample_offset(sy % n_, n_);
      for (int sx = 0; sx < xy_.cols; ++sx)
        uv[static_cast<std::size_t>(sx)] = {sx / n_ + subsample_offset(sx % n_, n_), v};
      const std::vector<cv::Point2d> xy = undistort(rig.camera(side), uv);
      auto* row = xy_.ptr<cv::Vec2f>(sy);
      for (int sx = 0; sx < xy_.cols; ++sx) {
        const cv::Point2d& p = xy[static_cast<std::size_t>(sx)];
        row[sx] = {static_cast<float>(p.x), static_cast<float>(p.y)};
      }
    }
  });
}

}  // namespace scw::host::scene
