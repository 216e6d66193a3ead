// SPDX-License-Identifier: Apache-2.0
// Frames of the synthetic stereo rig (host/scene/rig.hpp).
#include "host/scene/rig.hpp"

#include <cmath>

#include <opencv2/calib3d.hpp>

#include "host/warning/setup.hpp"

namespace scw::host::scene {
namespace {

/// OpenCV camera axes have y down, the vehicle's y up; the mounting has no other rotation.
const cv::Matx33d kFlipY(1, 0, 0, 0, -1, 0, 0, 0, 1);

}  // namespace

cv::Matx33d CameraModel::matrix() const { return {fx, 0, cx, 0, fy, cy, 0, 0, 1}; }

cv::Vec3d default_camera_in_vehicle() {
  // vehicle_origin is the bumper in (y-up) camera coordinates, so the camera sits at minus it.
  const Eigen::Vector3d o = host::warning::WarningSetup{}.vehicle_origin;
  return {-o.x(), -o.y(), -o.z()};
}

cv::Matx33d StereoRig::rotation() const {
  cv::Matx33d r;
  cv::Rodrigues(rotation_rodrigues, r);
  return r;
}

double StereoRig::baseline_m() const { return cv::norm(translation_m); }

cv::Matx33d StereoRig::left_axes() const {
  // Pitching down turns the optical axis (vehicle z) towards the road (vehicle -y).
  const double c = std::cos(pitch_rad), s = std::sin(pitch_rad);
  const cv::Matx33d pitch(1, 0, 0, 0, c, -s, 0, s, c);
  return pitch * kFlipY;
}

cv::Vec3d StereoRig::vehicle_to_left(const cv::Vec3d& p) const {
  return left_axes().t() * (p - camera_in_vehicle_m);
}

cv::Vec3d StereoRig::left_to_vehicle(const cv::Vec3d& p) const {
  return left_axes() * p + camera_in_vehicle_m;
}

cv::Vec3d StereoRig::left_dir_to_vehicle(const cv::Vec3d& d) const { return left_axes() * d; }

cv::Vec3d StereoRig::right_to_left(const cv::Vec3d& p) const {
  return rotation().t() * (p - translation_m);
}

cv::Vec3d StereoRig::centre_in_vehicle(Side s) const {
  return left_to_vehicle(s == Side::left ? cv::Vec3d(0, 0, 0) : right_to_left({0, 0, 0}));
}

cv::Matx33d StereoRig::camera_to_vehicle(Side s) const {
  return s == Side::left ? left_axes() : left_axes() * rotation().t();
}

}  // namespace scw::host::scene
