// SPDX-License-Identifier: Apache-2.0
// Scene objects (host/scene/scene.hpp).
#include "host/scene/scene.hpp"

namespace scw::host::scene {

const char* kind_name(Kind k) {
  switch (k) {
    case Kind::pedestrian: return "pedestrian";
    case Kind::cyclist: return "cyclist";
    case Kind::car: return "car";
    case Kind::kerb: return "kerb";
    case Kind::pavement: return "pavement";
    case Kind::building: return "building";
  }
  return "?";
}

SceneObject standing_box(int id, Kind kind, const cv::Vec3d& size, double centre_x,
                         double front_z, const SurfaceLook& look) {
  SceneObject o;
  o.id = id;
  o.kind = kind;
  o.box_min = {centre_x - 0.5 * size[0], 0.0, front_z};
  o.box_max = {centre_x + 0.5 * size[0], size[1], front_z + size[2]};
  o.texture_origin = o.box_min;
  o.look = look;
  return o;
}

}  // namespace scw::host::scene
