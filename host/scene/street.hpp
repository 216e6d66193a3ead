// SPDX-License-Identifier: Apache-2.0
// A residential street around the lane: kerbs and raised, textured pavements on both sides,
// building fronts behind them and cars parked along the right kerb (docs/scene.md, "Street
// presets"). What real streets put beside the tunnel, and what a warning must never be about.
#pragma once

#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "host/scene/scene.hpp"

namespace scw::host::scene {

/// A car's size (width along x, height, depth along z), metres: the parked cars here and the
/// presets' cars.
inline const cv::Vec3d kCar{1.80, 1.50, 4.20};

/// The street across (vehicle x, metres; the car drives along x = 0 in a 3.5 m lane).
struct StreetLayout {
  double right_kerb_x = 3.75;   // the lane, then a 2 m parking strip up to the right kerb
  double left_kerb_x = -5.25;   // the oncoming lane up to the left kerb
  double kerb_width_m = 0.15;   // the kerb stones, lighter than the pavement
  double kerb_height_m = 0.12;  // kerb and pavement stand this high above the road
  double pavement_width_m = 2.5;
  double front_garden_m = 0.5;  // between the pavement and the building fronts
  double near_z_m = 2.0;        // street parts are cut to z >= this (ahead of the bumper) ...
  double far_z_m = 150.0;       // ... and to z <= this
  std::vector<double> parked_car_z;  // front of each car parked along the right kerb
};

/// The street's boxes with the car at `ego_z` along the street (the street slides towards the
/// car as it drives): kerbs, pavements, building fronts (lengths, gaps and heights drawn from
/// `seed`, the same in every frame) and parked cars, each cut to the layout's z range with its
/// texture fixed to the street. Ids from `first_id` up, the same part keeping its id in every
/// frame.
std::vector<SceneObject> street_objects(const StreetLayout& s, double ego_z, std::uint32_t seed,
                                        int first_id);

}  // namespace scw::host::scene
