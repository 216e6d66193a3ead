// SPDX-License-Identifier: Apache-2.0
// The synthetic stereo rig: two distorted cameras, the right one slightly turned, mounted on the
// car where the warning stage assumes the camera is (docs/scene.md).
#pragma once

#include <opencv2/core.hpp>

namespace scw::host::scene {

/// One camera: pinhole intrinsics in pixels and OpenCV's five distortion coefficients
/// (k1 k2 p1 p2 k3). Pixel centres at integer coordinates (OpenCV's convention).
struct CameraModel {
  double fx = 0.0, fy = 0.0, cx = 0.0, cy = 0.0;
  cv::Vec<double, 5> dist{};

  cv::Matx33d matrix() const;
};

enum class Side { left, right };

/// The left camera's centre in vehicle coordinates (x right, y up, z ahead, origin on the road
/// below the bumper's centre): the inverse of the warning stage's default vehicle_origin, so the
/// truth and `scw run` place the bumper at the same spot.
cv::Vec3d default_camera_in_vehicle();

/// The one rig every preset is seen through; the defaults are that rig (docs/scene.md says why).
/// Camera frames are OpenCV's (x right, y down, z ahead); R and T follow cv::stereoCalibrate:
/// X_right = R X_left + T, in metres.
struct StereoRig {
  cv::Size image_size{1280, 480};
  double frame_rate_hz = 100.0;  // nominal; presets sample the motion more coarsely
  CameraModel left{1400.0, 1400.0, 641.5, 279.0, {-0.06, 0.015, 0.0004, -0.0003, 0.0}};
  CameraModel right{1402.0, 1401.0, 638.0, 281.5, {-0.055, 0.012, -0.0003, 0.0002, 0.0}};
  cv::Vec3d rotation_rodrigues{0.0025, -0.0035, 0.0040};  // R as a Rodrigues vector, rad
  cv::Vec3d translation_m{-0.300, 0.0015, -0.0010};        // T
  /// Left camera centre in vehicle coordinates; its axes are the vehicle's with y flipped,
  /// turned down by `pitch_rad` about the vehicle's x axis (no roll or yaw).
  cv::Vec3d camera_in_vehicle_m = default_camera_in_vehicle();
  /// The camera's downward pitch, rad: 0 in the thesis's presets; the street presets mount the
  /// camera 1 degree down, as a real rig rarely sits level (the warning stage assumes level
  /// axes, so a pitch shifts its heights by about Z * pitch).
  double pitch_rad = 0.0;

  const CameraModel& camera(Side s) const { return s == Side::left ? left : right; }
  cv::Matx33d rotation() const;  // R
  double baseline_m() const;     // |T|: what stereoRectify makes the rectified baseline

  /// Vehicle point -> left camera frame and back.
  cv::Vec3d vehicle_to_left(const cv::Vec3d& p) const;
  cv::Vec3d left_to_vehicle(const cv::Vec3d& p) const;
  /// A direction (no translation) from the left camera frame to vehicle axes.
  cv::Vec3d left_dir_to_vehicle(const cv::Vec3d& d) const;
  /// Right camera frame -> left: X_l = R^T (X_r - T).
  cv::Vec3d right_to_left(const cv::Vec3d& p) const;
  /// A camera's centre in vehicle coordinates.
  cv::Vec3d centre_in_vehicle(Side s) const;
  /// The rotation taking a direction in the camera's frame to vehicle axes.
  cv::Matx33d camera_to_vehicle(Side s) const;
  /// The left camera's axes in vehicle axes: the y flip, then the pitch.
  cv::Matx33d left_axes() const;
};

}  // namespace scw::host::scene
