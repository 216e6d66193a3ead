// SPDX-License-Identifier: Apache-2.0
// The preset scenes (host/scene/presets.hpp).
#include "host/scene/presets.hpp"

#include <cmath>

#include <stdexcept>
#include <string>
#include <utility>

#include "host/scene/street.hpp"

namespace scw::host::scene {
namespace {

// Sizes (width along x, height, depth along z), metres.
const cv::Vec3d kPedestrian{0.60, 1.75, 0.40};
const cv::Vec3d kCyclist{1.80, 1.80, 0.60};  // side on: long along x

/// An object's look: a grey mean between 60 and 150 (dark clothes, a light car), off the road's
/// 110 and below the sky's 170 .. 200 so the eye finds it, and a seed of its own.
SurfaceLook look(std::uint32_t seed, int id, double base) {
  return {seed * 1000003U + static_cast<std::uint32_t>(id), base, 40.0};
}

/// Position k of n evenly from a to b (both ends included), exact at the ends.
double lerp(double a, double b, int k, int n) {
  return k == n - 1 ? b : a + (b - a) * k / (n - 1);
}

struct Preset {
  const char* name;
  int frames;
};
constexpr Preset kPresets[] = {{"distance-sweep", 49},   {"cyclist-crossing", 57},
                               {"pedestrian-running", 38}, {"street-crossing", 41},
                               {"street-driving", 41}};

// The street presets: a camera pitched 1 degree down, dashed lane markings, and road grain the
// matcher finds in patches (+-25 while a pedestrian crosses, +-60 while driving).
constexpr double kStreetPitchRad = 1.0 * 3.141592653589793 / 180.0;
constexpr double kCrossingGrain = 25.0, kDrivingGrain = 60.0;

std::string names_list() {
  std::string s;
  for (const auto& p : kPresets) s += (s.empty() ? "" : ", ") + std::string(p.name);
  return s;
}

}  // namespace

std::vector<std::string> preset_names() {
  std::vector<std::string> v;
  for (const auto& p : kPresets) v.emplace_back(p.name);
  return v;
}

int default_frames(const std::string& preset) {
  for (const auto& p : kPresets)
    if (preset == p.name) return p.frames;
  throw std::invalid_argument("unknown scene preset '" + preset + "'; the presets are " +
                              names_list());
}

Sequence make_preset(const std::string& preset, std::optional<int> frames, std::uint32_t seed) {
  const int own = default_frames(preset);  // throws for an unknown name, frames given or not
  const int n = frames.value_or(own);
  if (n < 2)
    throw std::invalid_argument("scene preset '" + preset + "': " + std::to_string(n) +
                                " frames; give at least 2 (the motion's two ends)");
  Sequence s;
  s.preset = preset;
  s.seed = seed;
  for (int k = 0; k < n; ++k) {
    SceneFrame f;
    f.index = k;
    if (preset == "distance-sweep") {
      // Fig. 5.5: a pedestrian straight ahead, 30 m down to 6 m from the bumper in 0.5 m steps.
      // The thesis measured static poses; here the pedestrian walks slowly towards the car
      // (0.5 m/s, one pose a second by default), so a tracker sees a plausible speed.
      const double step = 24.0 / (n - 1);
      s.frame_period_s = step / 0.5;
      f.objects.push_back(standing_box(1, Kind::pedestrian, kPedestrian, 0.0,
                                       lerp(30.0, 6.0, k, n), look(seed, 1, 85.0)));
    } else if (preset == "cyclist-crossing") {
      // Fig. 5.12: a cyclist crossing 8 m ahead, left to right at 5 m/s.
      const double step = 14.0 / (n - 1);
      s.frame_period_s = step / 5.0;
      f.objects.push_back(standing_box(1, Kind::cyclist, kCyclist, lerp(-7.0, 7.0, k, n), 8.0,
                                       look(seed, 1, 70.0)));
    } else if (preset == "street-crossing") {
      // A pedestrian steps out between two cars parked along the right kerb 9 m ahead and
      // crosses the lane right to left at 1.5 m/s; the car stands.
      const double step = 6.0 / (n - 1);
      s.frame_period_s = step / 1.5;
      StreetLayout street;
      street.parked_car_z = {3.0, 13.0, 18.5, 30.0};
      f.objects.push_back(standing_box(1, Kind::pedestrian, kPedestrian, lerp(3.0, -3.0, k, n),
                                       9.0, look(seed, 1, 85.0)));
      for (auto& o : street_objects(street, 0.0, seed, 10)) f.objects.push_back(o);
      s.ground = {true, kCrossingGrain};
      s.pitch_rad = kStreetPitchRad;
    } else if (preset == "street-driving") {
      // The car drives 32 m down the street at 8 m/s past parked cars; nothing crosses.
      const double step = 32.0 / (n - 1);
      s.frame_period_s = step / 8.0;
      StreetLayout street;
      street.parked_car_z = {12.0, 17.5, 30.0, 45.0, 51.0};
      f.objects = street_objects(street, lerp(0.0, 32.0, k, n), seed, 10);
      s.ground = {true, kDrivingGrain};
      s.pitch_rad = kStreetPitchRad;
    } else {
      // Fig. 5.13: a pedestrian running at the car at 3 m/s past a parked car on the left.
      const double step = 18.5 / (n - 1);
      s.frame_period_s = step / 3.0;
      f.objects.push_back(standing_box(1, Kind::pedestrian, kPedestrian, -0.4,
                                       lerp(25.0, 6.5, k, n), look(seed, 1, 85.0)));
      f.objects.push_back(standing_box(2, Kind::car, kCar, -4.5, 14.0, look(seed, 2, 140.0)));
    }
    f.time_s = k * s.frame_period_s;
    s.frames.push_back(std::move(f));
  }
  return s;
}

}  // namespace scw::host::scene
