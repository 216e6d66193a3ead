// SPDX-License-Identifier: Apache-2.0
// The objects the application layer classifies (thesis 5.3.3): their five features, the three
// classes, and Table 5.4's statistics of the two named ones.
#pragma once

#include <array>
#include <cstddef>
#include <string>

namespace scw::app {

/// The five features of one object (thesis 5.3.3): Hu's first three invariants of its
/// silhouette (eq. 2.7) and its 3D width and height in metres (eq. 3.12). This order is the
/// order of every feature vector, CSV column and model file in this module.
struct Features {
  double hu1 = 0, hu2 = 0, hu3 = 0, width_m = 0, height_m = 0;
};

inline constexpr std::size_t kNumFeatures = 5;
/// The features' names, as in the CSV header: hu1, hu2, hu3, width_m, height_m.
extern const std::array<const char*, kNumFeatures> kFeatureNames;

/// The features as an array, in Features' order.
std::array<double, kNumFeatures> to_array(const Features& f);
/// The inverse of to_array.
Features from_array(const std::array<double, kNumFeatures>& a);

/// The thesis's classes. The values index ClassRates tables and are the labels the SVM and the
/// neural network are trained on (the network's output node k is class k), so they are fixed.
enum class ObjectClass { kOther = 0, kPedestrian = 1, kBike = 2 };
inline constexpr std::size_t kNumClasses = 3;
inline constexpr std::array<ObjectClass, kNumClasses> kAllClasses{
    ObjectClass::kOther, ObjectClass::kPedestrian, ObjectClass::kBike};

/// A class's index in ClassRates tables and kAllClasses.
inline constexpr std::size_t class_index(ObjectClass c) { return static_cast<std::size_t>(c); }

/// "other", "pedestrian" or "bike".
const char* to_string(ObjectClass c);
/// The inverse of to_string(ObjectClass) (exact, lower case); std::invalid_argument naming the
/// accepted names otherwise.
ObjectClass from_string(const std::string& s);

/// One row of a training or test set.
struct LabelledFeatures {
  ObjectClass cls = ObjectClass::kOther;
  Features f;
};

/// Per-feature mean and standard deviation of one class.
struct ClassStats {
  Features mean, sigma;
};

/// Table 5.4: 146 frames of pedestrians. (The table lists height before width.)
inline constexpr ClassStats kTable54Pedestrian{{0.326, 0.065, 0.002, 0.73, 1.80},
                                               {0.045, 0.030, 0.002, 0.07, 0.10}};
/// Table 5.4: 233 frames of persons on bikes.
inline constexpr ClassStats kTable54Bike{{0.276, 0.003, 0.016, 2.03, 1.82},
                                         {0.066, 0.006, 0.017, 0.15, 0.06}};

}  // namespace scw::app
