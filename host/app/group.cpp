// SPDX-License-Identifier: Apache-2.0
#include "host/app/group.hpp"

#include <cstdlib>
#include <numeric>

namespace scw::app {

std::vector<Target> group_objects(const std::vector<hls::labelling::Object>& objects,
                                  const std::vector<hls::warning::ObjectEval>& evals,
                                  const GroupParams& p) {
  const int n = static_cast<int>(objects.size());
  std::vector<int> parent(objects.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  auto touch = [&](const hls::labelling::Object& a, const hls::labelling::Object& b) {
    return a.x_min <= b.x_max + p.touch_px && b.x_min <= a.x_max + p.touch_px &&
           a.y_min <= b.y_max + p.touch_px && b.y_min <= a.y_max + p.touch_px;
  };
  const int max_dz_mm = static_cast<int>(p.max_dz_m * 1000.0);
  for (int i = 0; i < n; ++i) {
    if (!evals[i].measurable) continue;
    for (int j = i + 1; j < n; ++j) {
      if (!evals[j].measurable || !touch(objects[i], objects[j])) continue;
      if (std::abs(evals[i].z_mm - evals[j].z_mm) > max_dz_mm) continue;
      const int a = find(i), b = find(j);
      if (a != b) parent[b < a ? a : b] = b < a ? b : a;  // the earlier part names the target
    }
  }
  std::vector<Target> targets;
  std::vector<int> slot(objects.size(), -1);
  for (int i = 0; i < n; ++i) {
    if (!evals[i].measurable) continue;
    const int r = find(i);
    if (slot[r] < 0) {
      slot[r] = static_cast<int>(targets.size());
      targets.push_back({{i}, objects[i]});
    } else {
      Target& t = targets[slot[r]];
      t.parts.push_back(i);
      t.object = hls::labelling::merge(t.object, objects[i]);
    }
  }
  return targets;
}

}  // namespace scw::app
