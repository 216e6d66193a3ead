// SPDX-License-Identifier: Apache-2.0
// Synthetic feature rows drawn from Table 5.4's statistics: stand-ins for the thesis's samples.
#pragma once

#include <vector>

#include "host/app/object_features.hpp"

namespace scw::app {

/// Synthetic stand-ins for the thesis's samples, which are not public: per_class rows of each
/// class, pedestrians first, then bikes, then other. Pedestrian and bike features follow
/// Table 5.4's means and standard deviations, each drawn from the gamma distribution with that
/// mean and deviation (features are never negative; for hu1 and the sizes it is close to the
/// normal). "Other" rows (trees, bushes, poles, signs) are half broad clutter over and around
/// both classes and half look-alikes: a class's gamma with twice its deviation. The same seed
/// gives the same rows with any standard library (own samplers on std::mt19937, whose sequence
/// the standard fixes). docs/classify.md gives the details and what classifiers score on them.
std::vector<LabelledFeatures> synthesize_table54(int per_class, unsigned seed);

}  // namespace scw::app
