// SPDX-License-Identifier: Apache-2.0
// Ground truth of synthetic frames (host/scene/truth.hpp).
#include "host/scene/truth.hpp"

#include <algorithm>
#include <vector>

#include <opencv2/calib3d.hpp>

namespace scw::host::scene {

namespace {

/// Points of the box on a (kSteps + 1)^3 grid: at 16 steps a 1.8 m cyclist's grid is 11 cm, under
/// 20 px at 8 m, so a sliver the pair both see is not stepped over.
constexpr int kSteps = 16;

/// Whether each point of the left camera's frame lies in front of the camera whose frame is
/// `r` p + `t` and projects (with distortion) into its image: one projectPoints call for all.
std::vector<bool> in_image(const std::vector<cv::Point3d>& left_pts, const cv::Matx33d& r,
                           const cv::Vec3d& t, const CameraModel& cam, const cv::Size& size) {
  std::vector<cv::Point3d> pts;
  pts.reserve(left_pts.size());
  for (const auto& p : left_pts) {
    const cv::Vec3d q = r * cv::Vec3d(p.x, p.y, p.z) + t;
    pts.emplace_back(q[0], q[1], q[2]);
  }
  std::vector<cv::Point2d> uv;
  cv::projectPoints(pts, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0), cam.matrix(), cam.dist, uv);
  std::vector<bool> in(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i)
    in[i] = pts[i].z > 0.0 && uv[i].x >= -0.5 && uv[i].x <= size.width - 0.5 &&
            uv[i].y >= -0.5 && uv[i].y <= size.height - 0.5;
  return in;
}

}  // namespace

bool in_view(const SceneObject& o, const StereoRig& rig) {
  int ahead = 0;
  for (int c = 0; c < 8; ++c) {
    const cv::Vec3d v((c & 1) ? o.box_max[0] : o.box_min[0], (c & 2) ? o.box_max[1] : o.box_min[1],
                      (c & 4) ? o.box_max[2] : o.box_min[2]);
    ahead += rig.vehicle_to_left(v)[2] > 0.0;
  }
  if (ahead == 0) return false;
  if (ahead < 8) return true;  // across the camera's plane: beside the car
  // Stereo measures only what both cameras see: some point of the box in both images.
  std::vector<cv::Point3d> grid;
  for (int i = 0; i <= kSteps; ++i)
    for (int j = 0; j <= kSteps; ++j)
      for (int k = 0; k <= kSteps; ++k) {
        const cv::Vec3d t(double(i) / kSteps, double(j) / kSteps, double(k) / kSteps);
        cv::Vec3d v;
        for (int a = 0; a < 3; ++a) v[a] = o.box_min[a] + t[a] * (o.box_max[a] - o.box_min[a]);
        const cv::Vec3d p = rig.vehicle_to_left(v);
        grid.emplace_back(p[0], p[1], p[2]);
      }
  const auto left = in_image(grid, cv::Matx33d::eye(), {0, 0, 0}, rig.left, rig.image_size);
  const auto right = in_image(grid, rig.rotation(), rig.translation_m, rig.right, rig.image_size);
  for (std::size_t i = 0; i < grid.size(); ++i)
    if (left[i] && right[i]) return true;
  return false;
}

ObjectTruth object_truth(const SceneObject& o, const StereoRig& rig,
                         const host::warning::WarningSetup& w) {
  ObjectTruth t;
  t.id = o.id;
  t.kind = o.kind;
  t.box_min = o.box_min;
  t.box_max = o.box_max;
  const cv::Vec3d& cam = rig.camera_in_vehicle_m;
  for (int a = 0; a < 3; ++a) t.closest[a] = std::clamp(cam[a], o.box_min[a], o.box_max[a]);
  // Eq. 3.11 from the camera, less the camera's distance behind the bumper: how the warning
  // stage measures from the bumper.
  t.distance_m = cv::norm(t.closest - cam) - w.vehicle_origin.z();
  const double depth = rig.vehicle_to_left(t.closest)[2];
  t.disparity_px = depth > 0.0 ? rig.left.fx * rig.baseline_m() / depth : 0.0;

  const double hw = w.tunnel_half_width_m(), th = w.tunnel_height_m();
  const double gap = std::max({o.box_min[0] - hw, -hw - o.box_max[0], o.box_min[1] - th,
                               0.0 - o.box_max[1]});
  t.gap_m = std::max(0.0, gap);
  t.in_tunnel = gap <= 0.0;
  t.obstacle = o.box_max[1] - o.box_min[1] >= w.min_height_m;
  t.in_view = in_view(o, rig);
  if (t.obstacle) t.severity = judge_severity(t.in_tunnel, t.gap_m, t.distance_m, w);
  return t;
}

FrameTruth frame_truth(const SceneFrame& f, const StereoRig& rig,
                       const host::warning::WarningSetup& w) {
  FrameTruth ft;
  ft.frame = f.index;
  ft.time_s = f.time_s;
  const ObjectTruth* best = nullptr;
  for (const auto& o : f.objects) {
    ft.objects.push_back(object_truth(o, rig, w));
  }
  for (const auto& t : ft.objects) {
    if (!t.obstacle || !t.in_view) continue;
    if (!best || t.severity > best->severity ||
        (t.severity == best->severity &&
         (t.distance_m < best->distance_m ||
          (t.distance_m == best->distance_m && t.id < best->id))))
      best = &t;
  }
  if (best) {
    ft.severity = best->severity;
    ft.deciding = best->id;
    ft.distance_m = best->distance_m;
  }
  return ft;
}

}  // namespace scw::host::scene
