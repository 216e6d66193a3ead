// SPDX-License-Identifier: Apache-2.0
// What a synthetic frame holds: upright textured boxes in vehicle coordinates at one time.
#pragma once

#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "host/scene/texture.hpp"

namespace scw::host::scene {

/// What a box is. The street's own parts (kerb, pavement, building) are never what a warning
/// should be about, except a building front that stands in the way.
enum class Kind { pedestrian, cyclist, car, kerb, pavement, building };

/// "pedestrian", "cyclist", "car", "kerb", "pavement", "building".
const char* kind_name(Kind k);

/// An axis-aligned box in vehicle coordinates (x right, y up, z ahead, metres). The texture is
/// fixed to `texture_origin` (the box's minimum corner unless a long street part is cut to the
/// view), so it moves with the object.
struct SceneObject {
  int id = 0;  // the same object keeps its id in every frame
  Kind kind = Kind::pedestrian;
  cv::Vec3d box_min, box_max;
  cv::Vec3d texture_origin;
  SurfaceLook look;

  cv::Vec3d size() const { return box_max - box_min; }
};

/// A box standing on the road: `size` = (width along x, height along y, depth along z), centred
/// on `centre_x`, its face nearest the car at z = `front_z`.
SceneObject standing_box(int id, Kind kind, const cv::Vec3d& size, double centre_x,
                         double front_z, const SurfaceLook& look);

struct SceneFrame {
  int index = 0;
  double time_s = 0.0;
  std::vector<SceneObject> objects;
};

/// A preset's frames, evenly spaced in time.
struct Sequence {
  std::string preset;
  double frame_period_s = 0.0;
  std::uint32_t seed = 1;  // textures (road and objects) and camera noise
  std::vector<SceneFrame> frames;
  GroundLook ground;       // the road's grain and markings
  double pitch_rad = 0.0;  // the rig's downward pitch (StereoRig::pitch_rad)
};

}  // namespace scw::host::scene
