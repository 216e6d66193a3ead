// SPDX-License-Identifier: Apache-2.0
// Floating-point reference for the warning stage: eq. 2.18, 3.11, 3.12 and 5.2 in metres with
// Eigen, written from the formulas so the fixed-point evaluate() can be checked against it.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "hls/labelling/labelling_params.hpp"
#include "hls/warning/warning_params.hpp"
#include "host/reference/road_ref.hpp"
#include "host/warning/setup.hpp"

namespace scw::host::warning {

/// One object as the reference sees it. Lengths in metres, camera coordinates (x right, y up,
/// z ahead) unless said otherwise.
struct RefEval {
  bool measurable = false;    // the rule's disparity d is at least 1 px
  bool too_close = false;     // d_max >= the setup's d_limit_px
  double disparity_px = 0.0;  // d: rule_disparity_px, every coordinate's depth
  Eigen::Vector3d closest = Eigen::Vector3d::Zero();  // A, eq. 2.18 at the closest pixel
  /// Bounding-box corners C_LU and C_RB at A's depth, through the pixel edges
  /// (x_min - 1/2, y_min - 1/2) and (x_max + 1/2, y_max + 1/2).
  Eigen::Vector3d top_left = Eigen::Vector3d::Zero();
  Eigen::Vector3d bottom_right = Eigen::Vector3d::Zero();
  double width_m = 0.0, height_m = 0.0;  // eq. 3.12
  double above_road_m = 0.0;  // with a road: the top's height above it where the object stands
  double camera_distance_m = 0.0;        // |A|, eq. 3.11
  double distance_m = 0.0;               // |A| - vehicle_origin.z: from the bumper
  /// The box's separation from the tunnel's cross-section: the largest of the four amounts by
  /// which it lies left, right, above or below the tunnel; <= 0 when they overlap.
  double signed_gap_m = 0.0;
  double gap_m = 0.0;  // max(0, signed_gap_m)
  bool in_tunnel = false;
  bool obstacle = false;  // measurable, height_m >= min_height_m (and above_road_m, with a road)
  hls::warning::Severity severity = hls::warning::Severity::kNone;

  /// The distance eq. 5.2 is applied to: 0 for a too-close object (judged as at the bumper).
  double judged_distance_m() const { return too_close ? 0.0 : distance_m; }
};

/// The frame's outcome: the deciding obstacle (worst severity, then the smallest judged distance,
/// then the earliest in the table), or none.
struct RefFrame {
  hls::warning::Severity severity = hls::warning::Severity::kNone;
  int index = -1;  // position of the deciding object in the table, -1 = no obstacle
  int objects = 0;
  int obstacles = 0;
  RefEval deciding;  // valid when index >= 0
};

/// Eq. 5.2 and section 5.4 on an obstacle, as docs/warning.md states them: in the tunnel high if
/// D <= high, medium if D < medium, else low; outside, medium if the gap is at most near and
/// D < medium, else low. The reference and the synthetic scenes' truth both judge with it.
hls::warning::Severity judge_severity(bool in_tunnel, double gap_m, double distance_m,
                                      const WarningSetup& s);

/// The disparity (px) that places `o` under the setup's rule: d_max / 16 (kClosest), or
/// min(d_max, mean + spread_k sd) of its disparities from its area, sum and sum of squares
/// (kSpread; d_max when the area is 0).
double rule_disparity_px(const hls::labelling::Object& o, const WarningSetup& s);

/// Evaluates one labelling object in double precision: no integer arithmetic, thresholds taken
/// from `s` in metres as given (not rounded to the stage's millimetres). With `road` (the frame's
/// road line, as the pipeline's warning stage has it) an obstacle's top must also lie
/// min_height above the road where the object stands: the road's disparity at the box's top
/// edge is d_road = a (y_min - 1/2) + b, the object stands where it is d, and a flat road seen
/// from height H = baseline / a puts the top H (d - d_road) / d above it.
RefEval evaluate_ref(const hls::labelling::Object& o, const WarningSetup& s,
                     const reference::RoadLinePx* road = nullptr);

/// How far the stage's distance may lie from the reference's for object `e`: 1 cm of fixed-point
/// arithmetic, and under the spread rule one Q11.4 code of the rule's rounding (|A| / (16 d)).
double distance_tolerance_m(const RefEval& e, const WarningSetup& s);

/// Evaluates a frame's object table (with its road, when given) and picks the deciding obstacle.
RefFrame fold_ref(const std::vector<hls::labelling::Object>& objects, const WarningSetup& s,
                  const reference::RoadLinePx* road = nullptr);

}  // namespace scw::host::warning
