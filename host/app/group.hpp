// SPDX-License-Identifier: Apache-2.0
// Groups the labelling stage's objects into physical targets: block matching splits a cyclist
// into body and wheel parts at disparity steps the join rule (eq. 3.10) does not bridge, so
// parts that touch in the image at nearly the same depth are one target for classification,
// tracking and the overlay (docs/warning.md, "`scw run`").
#pragma once

#include <vector>

#include "hls/labelling/labelling_params.hpp"
#include "hls/warning/warning_params.hpp"

namespace scw::app {

struct GroupParams {
  int touch_px = 4;         // image boxes within this many pixels of each other touch
  double max_dz_m = 0.6;    // closest points at most this far apart in depth
};

/// One target: its parts (indices into the object list) and their union descriptor
/// (hls::labelling::merge: box, moments, closest point).
struct Target {
  std::vector<int> parts;
  hls::labelling::Object object;
};

/// Targets of measurable objects (evals[i].measurable), in order of their first part.
std::vector<Target> group_objects(const std::vector<hls::labelling::Object>& objects,
                                  const std::vector<hls::warning::ObjectEval>& evals,
                                  const GroupParams& p = {});

}  // namespace scw::app
