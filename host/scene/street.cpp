// SPDX-License-Identifier: Apache-2.0
// The street around the lane (host/scene/street.hpp).
#include "host/scene/street.hpp"

#include <algorithm>

namespace scw::host::scene {
namespace {

// Looks: paving slabs lighter than the asphalt (110) with their own grain, kerb stones lighter
// still, building fronts from dark brick to light render.
constexpr double kPavementGrey = 135.0, kPavementContrast = 30.0;
constexpr double kKerbGrey = 165.0, kKerbContrast = 16.0;
constexpr double kBuildingDepth = 10.0;

/// A uniform number in [0, 1) from a key (the street's layout is the same in every frame).
double unit(std::uint32_t key) {
  key ^= key >> 16;
  key *= 0x7feb352dU;
  key ^= key >> 15;
  key *= 0x846ca68bU;
  key ^= key >> 16;
  return key / 4294967296.0;
}

/// A box of the street from world z0 to z1 (street coordinates), shifted by the car's travel and
/// cut to the view's range; false when nothing of it is left.
bool street_box(SceneObject& o, double x0, double x1, double h, double z0, double z1,
                double ego_z, const StreetLayout& s) {
  const double a = std::max(z0 - ego_z, s.near_z_m), b = std::min(z1 - ego_z, s.far_z_m);
  if (!(b > a)) return false;
  o.box_min = {x0, 0.0, a};
  o.box_max = {x1, h, b};
  o.texture_origin = {x0, 0.0, z0 - ego_z};
  return true;
}

}  // namespace

std::vector<SceneObject> street_objects(const StreetLayout& s, double ego_z, std::uint32_t seed,
                                        int first_id) {
  std::vector<SceneObject> out;
  // Fixed id ranges, so a part keeps its id while others leave the view: parked cars from
  // first_id, kerbs and pavements from first_id + 50, each side's buildings from + 100 and
  // + 1100.
  auto add = [&](int id, Kind kind, double x0, double x1, double h, double z0, double z1,
                 const SurfaceLook& look) {
    SceneObject o;
    o.id = id;
    o.kind = kind;
    o.look = look;
    if (street_box(o, x0, x1, h, z0, z1, ego_z, s)) out.push_back(o);
  };
  const double z_begin = -50.0, z_end = s.far_z_m + ego_z + 50.0;
  for (int side = 0; side < 2; ++side) {
    const bool right = side == 0;
    const double dir = right ? 1.0 : -1.0;
    const double kerb = right ? s.right_kerb_x : s.left_kerb_x;
    const double kerb_out = kerb + dir * s.kerb_width_m;
    const double pave_out = kerb_out + dir * s.pavement_width_m;
    const double front = pave_out + dir * s.front_garden_m;
    const std::uint32_t key = seed * 7919U + static_cast<std::uint32_t>(side) * 104729U;
    add(first_id + 50 + 2 * side, Kind::kerb, std::min(kerb, kerb_out), std::max(kerb, kerb_out), s.kerb_height_m, z_begin,
        z_end, {key + 1U, kKerbGrey, kKerbContrast});
    add(first_id + 51 + 2 * side, Kind::pavement, std::min(kerb_out, pave_out), std::max(kerb_out, pave_out),
        s.kerb_height_m, z_begin, z_end, {key + 2U, kPavementGrey, kPavementContrast});
    // Building fronts: 10 to 25 m long, 3 to 6 m apart, 6 to 12 m high.
    double z = z_begin;
    for (std::uint32_t k = 0; z < z_end; ++k) {
      const std::uint32_t b = key + 100U + 3U * k;
      const double length = 10.0 + 15.0 * unit(b), height = 6.0 + 6.0 * unit(b + 1U);
      const double grey = 80.0 + 70.0 * unit(b + 2U);
      const double x_far = front + dir * kBuildingDepth;
      add(first_id + 100 + 1000 * side + static_cast<int>(k), Kind::building, std::min(front, x_far), std::max(front, x_far), height, z, z + length,
          {b, grey, 50.0});
      z += length + 3.0 + 3.0 * unit(b + 7U);
    }
  }
  // Parked cars in the right parking strip, 0.1 m from the kerb.
  const double car_x = s.right_kerb_x - 0.1 - 0.5 * kCar[0];
  for (std::size_t k = 0; k < s.parked_car_z.size(); ++k) {
    const double z0 = s.parked_car_z[k];
    add(first_id + static_cast<int>(k), Kind::car, car_x - 0.5 * kCar[0], car_x + 0.5 * kCar[0], kCar[1], z0, z0 + kCar[2],
        {seed * 31U + 500U + static_cast<std::uint32_t>(k), 60.0 + 20.0 * (k % 4), 40.0});
  }
  return out;
}

}  // namespace scw::host::scene
