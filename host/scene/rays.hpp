// SPDX-License-Identifier: Apache-2.0
// The rays of a camera's sub-samples in vehicle coordinates: lens distortion inverted once per
// rig, then reused for every frame (docs/scene.md).
#pragma once

#include <vector>

#include <opencv2/core.hpp>

#include "host/scene/rig.hpp"

namespace scw::host::scene {

/// Where sub-sample k of n lies from its pixel's centre, in pixels: centres of n equal parts
/// ((k + 1/2) / n - 1/2; -1/3, 0, +1/3 for n = 3).
double subsample_offset(int k, int n);

/// Undistorted normalised coordinates (x/z, y/z in the camera's frame) of raw pixel positions,
/// by cv::undistortPoints iterated to 1e-12 px (at most 20 iterations). Its default of 5 already
/// lands within 1.5e-7 px with this mild lens; iterating to convergence keeps the inverse exact
/// to rounding for a stronger one, for about a second more per table.
std::vector<cv::Point2d> undistort(const CameraModel& cam, const std::vector<cv::Point2d>& uv);

/// The direction (not normalised) of the ray through raw position `uv` of camera `side`, in
/// vehicle coordinates: what the table holds, at any position and in double precision.
cv::Vec3d ray_direction(const StereoRig& rig, Side side, cv::Point2d uv);

/// Every sub-sample ray of one camera. Sample column sx = u * n + i, row sy = v * n + j is
/// sub-sample (i, j) of pixel (u, v), at (u + subsample_offset(i, n), v + subsample_offset(j, n)).
class RayTable {
 public:
  RayTable(const StereoRig& rig, Side side, int subsamples);

  int subsamples() const { return n_; }
  cv::Size image_size() const { return size_; }
  /// Focal length of the camera, px: a pixel subtends 1 / focal_px() rad near the axis.
  double focal_px() const { return focal_px_; }
  /// The camera centre, vehicle coordinates.
  const cv::Vec3d& origin() const { return origin_; }
  /// The ray of sample (sx, sy), vehicle axes, not normalised (its camera-frame z is 1).
  cv::Vec3d direction(int sx, int sy) const {
    const cv::Vec2f& p = xy_.at<cv::Vec2f>(sy, sx);
    return to_vehicle_ * cv::Vec3d(p[0], p[1], 1.0);
  }

 private:
  int n_;
  cv::Size size_;
  double focal_px_;
  cv::Vec3d origin_;
  cv::Matx33d to_vehicle_;
  cv::Mat xy_;  // CV_32FC2, (height n) x (width n): normalised coordinates; float keeps the
                // table at 44 MB a camera and its rays within 1e-7 rad
};

}  // namespace scw::host::scene
