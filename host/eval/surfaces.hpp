// SPDX-License-Identifier: Apache-2.0
// What the deciding object is: the scene surface most of its pixels see. A synthetic scene knows
// what every pixel shows, so `scw eval` can say whether the warning was decided by a pedestrian,
// a parked car, or the road, a kerb or a pavement (which never should decide: docs/eval.md).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "host/eval/compare.hpp"
#include "host/scene/rig.hpp"
#include "host/scene/scene.hpp"

namespace scw::host::eval {

/// A scene folder seen again: its frames rebuilt from scene.json (preset, frames, seed), the rig
/// with its pitch, and the left camera's rectified-to-raw map as `scw run` rectifies it.
struct SceneView {
  scene::StereoRig rig;
  std::vector<scene::SceneFrame> frames;
  std::uint32_t seed = 1;
  cv::Mat map_x, map_y;  // CV_32FC1: raw left x, y for each rectified left pixel
};

/// The scene of `dir` (scw scene's folder), or nullopt when it has no scene.json naming a known
/// preset (a truth file made elsewhere). Throws std::runtime_error when scene.json or
/// calibration.yml is there but broken.
std::optional<SceneView> load_scene_view(const std::filesystem::path& dir);

/// The surface most pixels of one object see: a kind name ("pedestrian", "car", "pavement",
/// ...), "road" (markings included) or "sky"; and the share of the object's pixels that see it.
struct Surface {
  std::string name;
  double share = 0.0;
};

/// `labels`: the CV_16UC1 label picture `scw run` wrote for the frame; `label`: the deciding
/// object's number in it. Each of its pixels is traced back through the rectification into the
/// scene. Throws std::runtime_error when the picture does not match the rectified size or holds
/// no pixel of `label`.
Surface object_surface(const SceneView& view, int frame, const cv::Mat& labels, int label);

/// The street's own surfaces, which should never decide a warning: road (and its markings),
/// kerb, pavement.
bool is_street_surface(const std::string& name);

/// Fills every frame's deciding_surface from the label pictures `scw run` wrote beside its
/// results (NNNN_labels.png in `results_dir`). Throws std::runtime_error naming a missing or
/// unreadable picture.
void trace_deciding_surfaces(EvalReport& report, const SceneView& view,
                             const std::filesystem::path& results_dir);

}  // namespace scw::host::eval
