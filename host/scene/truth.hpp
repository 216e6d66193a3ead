// SPDX-License-Identifier: Apache-2.0
// Ground truth of a synthetic frame, by the warning stage's definitions (docs/warning.md):
// distance from the bumper, driving tunnel, eq. 5.2, the deciding object.
#pragma once

#include <vector>

#include <opencv2/core.hpp>

#include "hls/warning/warning_params.hpp"
#include "host/scene/rig.hpp"
#include "host/scene/scene.hpp"
#include "host/warning/reference.hpp"
#include "host/warning/setup.hpp"

namespace scw::host::scene {

using hls::warning::Severity;

/// One object's truth. Lengths in metres, vehicle coordinates (x right, y up, z ahead).
struct ObjectTruth {
  int id = 0;
  Kind kind = Kind::pedestrian;
  cv::Vec3d box_min, box_max;
  cv::Vec3d closest;          // the box's point nearest the left camera centre (Euclidean)
  double distance_m = 0.0;    // |closest - camera centre| - vehicle_origin.z: from the bumper
  double disparity_px = 0.0;  // f b / Z: left fx, |T|, Z = closest's depth in the left camera
  bool in_tunnel = false;     // the box's x and y intervals overlap the tunnel's cross-section
  double gap_m = 0.0;         // how far the box lies outside the cross-section; 0 inside
  bool obstacle = false;      // at least min_height_m high
  bool in_view = false;       // some point of the box is in both cameras' images
  Severity severity = Severity::kNone;  // eq. 5.2; kNone when not an obstacle
};

/// A frame's truth: the worst severity over the obstacles in view and the one that decides it
/// (worst severity, then the smallest distance, then the smallest id).
struct FrameTruth {
  int frame = 0;
  double time_s = 0.0;
  Severity severity = Severity::kNone;
  int deciding = -1;          // the deciding object's id; -1: no obstacle in view
  double distance_m = 0.0;    // the deciding object's distance (when there is one)
  std::vector<ObjectTruth> objects;
};

using hls::warning::severity_name;  // the names `scw run` writes

/// Eq. 5.2 as the floating-point warning reference judges it (host/warning/reference.hpp).
using host::warning::judge_severity;

/// Whether stereo can see some of the box: all of it in front of the left camera and a point of
/// it (on a grid of the box) in both images, with distortion; or the box reaching across the
/// camera's plane (beside the car). A point only one camera sees has no disparity.
bool in_view(const SceneObject& o, const StereoRig& rig);

/// The truth of one object; the tunnel and thresholds are `w`'s (default: WarningSetup's).
ObjectTruth object_truth(const SceneObject& o, const StereoRig& rig,
                         const host::warning::WarningSetup& w = {});

FrameTruth frame_truth(const SceneFrame& f, const StereoRig& rig,
                       const host::warning::WarningSetup& w = {});

}  // namespace scw::host::scene
