// SPDX-License-Identifier: Apache-2.0
// Ground truth of synthetic frames (host/scene/truth.hpp).
#include "host/scene/truth.hpp"

#include <algorithm>
#include <vector>

#include <opencv2/calib3d.hpp>

namespace scw::host::scene {

bool in_view(const SceneObject& o, const StereoRig& rig) {
  std::vector<cv::Point3d> corners;
  int ahead = 0;
  for (int c = 0; c < 8; ++c) {
    const cv::Vec3d v((c & 1) ? o.box_max[0] : o.box_min[0], (c & 2) ? o.box_max[1] : o.box_min[1],
                      (c & 4) ? o.box_max[2] : o.box_min[2]);
    const cv::Vec3d p = rig.vehicle_to_left(v);
    corners.emplace_back(p[0], p[1], p[2]);
    ahead += p[2] > 0.0;
  }
  if (ahead == 0) return false;
  if (ahead < 8) return true;  // across the camera's plane: beside the car
  std::vector<cv::Point2d> uv;
  cv::projectPoints(corners, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0), rig.left.matrix(),
                    rig.left.dist, uv);
  // The box's image is the hull of its corners' (the lens bends edges by a pixel or so).
  const auto [u0, u1] = std::minmax_element(uv.begin(), uv.end(),
                                            [](const auto& a, const auto& b) { return a.x < b.x; });
  const auto [v0, v1] = std::minmax_element(uv.begin(), uv.end(),
                                            [](const auto& a, const auto& b) { return a.y < b.y; });
  const double w = rig.image_size.width - 0.5, h = rig.image_size.height - 0.5;
  return u1->x >= -0.5 && u0->x <= w && v1->y >= -0.5 && v0->y <= h;
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
