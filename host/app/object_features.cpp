// SPDX-License-Identifier: Apache-2.0
// The features' names and arrays, the classes' names (host/app/object_features.hpp).
#include "host/app/object_features.hpp"

#include <stdexcept>

namespace scw::app {

const std::array<const char*, kNumFeatures> kFeatureNames{"hu1", "hu2", "hu3", "width_m",
                                                          "height_m"};

std::array<double, kNumFeatures> to_array(const Features& f) {
  return {f.hu1, f.hu2, f.hu3, f.width_m, f.height_m};
}

Features from_array(const std::array<double, kNumFeatures>& a) {
  return {a[0], a[1], a[2], a[3], a[4]};
}

const char* to_string(ObjectClass c) {
  switch (c) {
    case ObjectClass::kPedestrian:
      return "pedestrian";
    case ObjectClass::kBike:
      return "bike";
    case ObjectClass::kOther:
      break;
  }
  return "other";
}

ObjectClass from_string(const std::string& s) {
  for (const ObjectClass c : kAllClasses)
    if (s == to_string(c)) return c;
  throw std::invalid_argument("unknown class '" + s + "'; expected pedestrian, bike or other");
}

}  // namespace scw::app
