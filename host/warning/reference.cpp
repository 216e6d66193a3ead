// SPDX-License-Identifier: Apache-2.0
// The warning stage's floating-point reference (docs/warning-reference.md).
#include "host/warning/reference.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

namespace scw::host::warning {

using hls::warning::Severity;

namespace {

/// Eq. 2.18: the camera-frame point seen at image position (u, v) with disparity d px.
Eigen::Vector3d triangulate(double u, double v, double d, const WarningSetup& s) {
  return Eigen::Vector3d(s.baseline_m * (u - s.cu_px) / d, s.baseline_m * (s.cv_px - v) / d,
                         s.baseline_m * s.focal_px / d);
}

}  // namespace

double rule_disparity_px(const hls::labelling::Object& o, const WarningSetup& s) {
  const double d_max = static_cast<std::int16_t>(o.d_max) / 16.0;
  if (s.distance_rule != hls::warning::DistanceRule::kSpread) return d_max;
  if (o.area == 0) return d_max;
  const double n = o.area;
  const double mean = static_cast<double>(o.sum_d) / n / 16.0;
  const double var = static_cast<double>(o.sum_dd) / n / 256.0 - mean * mean;
  return std::min(d_max, mean + s.spread_k * std::sqrt(std::max(0.0, var)));
}

double distance_tolerance_m(const RefEval& e, const WarningSetup& s) {
  const bool spread = s.distance_rule == hls::warning::DistanceRule::kSpread;
  return 0.01 + (spread && e.disparity_px > 0 ? e.camera_distance_m / (16 * e.disparity_px) : 0);
}

RefEval evaluate_ref(const hls::labelling::Object& o, const WarningSetup& s,
                     const reference::RoadLinePx* road) {
  RefEval r;
  // The disparity word is a signed Q11.4 number: codes with the top bit set are negative
  // (invalid), and below 1 px the object is too far to place.
  const double d_max = static_cast<std::int16_t>(o.d_max) / 16.0;
  const double d = rule_disparity_px(o, s);
  r.disparity_px = d;
  r.measurable = d >= 1.0;
  if (!r.measurable) return r;
  r.too_close = d_max >= s.d_limit_px;

  r.closest = triangulate(o.closest_x, o.closest_y, d, s);
  // Every pixel covers [u - 1/2, u + 1/2], so the box reaches half a pixel past its outer
  // centres and a one-pixel object still has a size.
  r.top_left = triangulate(o.x_min - 0.5, o.y_min - 0.5, d, s);
  r.bottom_right = triangulate(o.x_max + 0.5, o.y_max + 0.5, d, s);
  r.width_m = r.bottom_right.x() - r.top_left.x();
  r.height_m = r.top_left.y() - r.bottom_right.y();

  r.camera_distance_m = r.closest.norm();
  // The camera sits vehicle_origin.z behind the bumper (Fig. 5.4: 7.89 m -> 6.24 m).
  r.distance_m = r.camera_distance_m - s.vehicle_origin.z();

  // The box's cross-section in vehicle coordinates (origin on the ground below the bumper's
  // centre), against the tunnel |x| <= half width, 0 <= y <= height.
  const Eigen::Vector3d lu = r.top_left - s.vehicle_origin;
  const Eigen::Vector3d rb = r.bottom_right - s.vehicle_origin;
  const double hw = s.tunnel_half_width_m(), th = s.tunnel_height_m();
  const double right_of = lu.x() - hw;  // > 0: the box starts right of the tunnel
  const double left_of = -hw - rb.x();  // > 0: the box ends left of it
  const double above = rb.y() - th;     // > 0: the box's bottom is above the roof
  const double below = 0.0 - lu.y();    // > 0: the box's top is below the road
  r.signed_gap_m = std::max({right_of, left_of, above, below});
  r.gap_m = std::max(0.0, r.signed_gap_m);
  r.in_tunnel = r.gap_m == 0.0;

  r.obstacle = r.height_m >= s.min_height_m;
  if (road != nullptr) {
    const double d_road = road->a * (o.y_min - 0.5) + road->b;
    // baseline (d - d_road) >= min_height a d, as the stage compares it (a = 0: a road at one
    // disparity puts every object nearer than it above it)
    const double rise = s.baseline_m * (d - d_road);
    r.above_road_m = road->a > 0 ? rise / (road->a * d) : (rise >= 0 ? HUGE_VAL : -HUGE_VAL);
    r.obstacle = r.obstacle && rise >= s.min_height_m * road->a * d;
  }
  if (!r.obstacle) return r;
  r.severity = judge_severity(r.in_tunnel, r.gap_m, r.judged_distance_m(), s);
  return r;
}

Severity judge_severity(bool in_tunnel, double gap_m, double distance_m, const WarningSetup& s) {
  if (in_tunnel)  // eq. 5.2
    return distance_m <= s.high_m ? Severity::kHigh
           : distance_m < s.medium_m ? Severity::kMedium
                                     : Severity::kLow;
  // Section 5.4: outside the tunnel at most medium, and only when near it and not far ahead.
  return gap_m <= s.near_m && distance_m < s.medium_m ? Severity::kMedium : Severity::kLow;
}

RefFrame fold_ref(const std::vector<hls::labelling::Object>& objects, const WarningSetup& s,
                  const reference::RoadLinePx* road) {
  RefFrame f;
  for (std::size_t i = 0; i < objects.size(); ++i) {
    const RefEval e = evaluate_ref(objects[i], s, road);
    ++f.objects;
    if (!e.obstacle) continue;
    ++f.obstacles;
    const bool first = f.index < 0;
    // Strict comparisons keep the earlier object on a tie.
    const bool worse = !first && e.severity > f.deciding.severity;
    const bool nearer = !first && e.severity == f.deciding.severity &&
                        e.judged_distance_m() < f.deciding.judged_distance_m();
    if (first || worse || nearer) {
      f.index = static_cast<int>(i);
      f.deciding = e;
      f.severity = e.severity;
    }
  }
  return f;
}

}  // namespace scw::host::warning
