// SPDX-License-Identifier: Apache-2.0
// Object tables for the warning stage's tests and golden vectors (shared fixtures, so they live in
// the product, not in tests/): camera setups, objects placed in 3D, random tables that
// reach every branch of the stage, and a plain fold of evaluate() to check frame results by.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "hls/labelling/labelling_params.hpp"
#include "hls/warning/warning_params.hpp"
#include "host/warning/setup.hpp"

namespace scw::fixtures {

using hls::labelling::Object;
using hls::warning::FrameResult;
using hls::warning::ObjectEval;
using hls::warning::Severity;
using hls::warning::WarningConfig;

/// The Karlsruhe pair's assumed rig (1344 x 391) and a thesis-like one (1280 x 480).
inline host::warning::WarningSetup karlsruhe_setup() {
  host::warning::WarningSetup s;
  s.cu_px = 672.0;
  s.cv_px = 195.5;
  s.d_limit_px = 127.0;
  return s;
}
inline host::warning::WarningSetup thesis_setup() {
  host::warning::WarningSetup s;
  s.focal_px = 1000.0;
  s.baseline_m = 0.6;
  s.cu_px = 640.0;
  s.cv_px = 240.0;
  s.d_limit_px = 64.0;
  return s;
}

/// Sets d_max to `dq` and the disparity sums to those of `area` pixels all at `dq` (sum_d =
/// A dq, sum_dd = A dq^2): under either distance rule such an object is placed at dq.
inline void set_uniform_code(Object& o, std::uint16_t dq) {
  o.d_max = dq;
  o.sum_d = std::uint64_t{o.area} * dq;
  o.sum_dd = std::uint64_t{o.area} * dq * dq;
}

/// Gives `o` a small random multiset of disparities whose largest is its d_max: 1 .. 12 pixels
/// (the area), the others spread up to an eighth of d_max below it; sum_d and sum_dd are theirs.
inline void set_random_sums(std::mt19937& rng, Object& o) {
  const std::uint32_t n = 1 + rng() % 12;
  const std::uint32_t spread = 1 + o.d_max / 8;
  o.area = n;
  o.sum_d = o.d_max;
  o.sum_dd = std::uint64_t{o.d_max} * o.d_max;
  for (std::uint32_t i = 1; i < n; ++i) {
    const std::uint64_t d = o.d_max - std::min<std::uint32_t>(o.d_max, rng() % spread);
    o.sum_d += d;
    o.sum_dd += d * d;
  }
}

/// An upright box standing on the road (camera coordinates, metres: lateral centre x, depth z,
/// size w x h) as the labelling stage would describe it: every pixel at the box's disparity.
inline Object place_box(const host::warning::WarningSetup& s, double x, double z, double w,
                        double h) {
  const double d = s.baseline_m * s.focal_px / z;  // px
  const double y_ground = s.vehicle_origin.y();
  auto u = [&](double xx) { return s.cu_px + s.focal_px * xx / z; };
  auto v = [&](double yy) { return s.cv_px - s.focal_px * yy / z; };
  Object o;
  o.x_min = static_cast<std::uint16_t>(std::lround(u(x - w / 2)));
  o.x_max = static_cast<std::uint16_t>(std::lround(u(x + w / 2)));
  o.y_min = static_cast<std::uint16_t>(std::lround(v(y_ground + h)));
  o.y_max = static_cast<std::uint16_t>(std::lround(v(y_ground)));
  o.d_min = static_cast<std::uint16_t>(std::lround(16 * d));
  o.closest_x = static_cast<std::uint16_t>((o.x_min + o.x_max) / 2);
  o.closest_y = o.y_max;
  o.area = 1u + (o.x_max - o.x_min) * (o.y_max - o.y_min);
  set_uniform_code(o, o.d_min);
  return o;
}

/// Random tables over the whole range of the stage: objects too far to measure, too close,
/// too low, in and beside the tunnel at every distance, with frequent exact ties. Each object
/// but the ties has a small random multiset of disparities up to its d_max (set_random_sums).
inline std::vector<Object> random_table(std::mt19937& rng, const host::warning::WarningSetup& s,
                                        int n, int width, int height) {
  std::uniform_int_distribution<int> kind(0, 9);
  std::uniform_real_distribution<double> lateral(-6.0, 6.0), depth(2.0, 40.0), size(0.1, 2.5);
  std::vector<Object> t;
  for (int i = 0; i < n; ++i) {
    // Drawn one by one, last argument first, as the committed sets were made: a call's arguments
    // are evaluated in an unspecified order (g++ went right to left, clang left to right).
    const double h = size(rng), w = size(rng), z = depth(rng), x = lateral(rng);
    Object o = place_box(s, x, z, w, h);
    bool copy = false;
    switch (kind(rng)) {
      case 0: o.d_max = static_cast<std::uint16_t>(rng() % 16); break;  // not measurable
      case 1: o.d_max = static_cast<std::uint16_t>(16 * s.d_limit_px + rng() % 64); break;
      case 2:  // an exact tie
        if (!t.empty()) {
          o = t[rng() % t.size()];
          copy = true;
        }
        break;
      default: break;
    }
    if (!copy) set_random_sums(rng, o);
    o.x_min = std::min<std::uint16_t>(o.x_min, static_cast<std::uint16_t>(width - 1));
    o.x_max = std::clamp<std::uint16_t>(o.x_max, o.x_min, static_cast<std::uint16_t>(width - 1));
    o.y_min = std::min<std::uint16_t>(o.y_min, static_cast<std::uint16_t>(height - 1));
    o.y_max = std::clamp<std::uint16_t>(o.y_max, o.y_min, static_cast<std::uint16_t>(height - 1));
    o.closest_x = std::clamp(o.closest_x, o.x_min, o.x_max);
    o.closest_y = std::clamp(o.closest_y, o.y_min, o.y_max);
    t.push_back(o);
  }
  return t;
}

/// The frame result by a plain loop over evaluate(): the deciding object has the highest
/// severity, then the smallest distance (0 when too close), then the smallest index.
template <typename Params>
FrameResult fold_table(const std::vector<Object>& t, const WarningConfig& c) {
  FrameResult r;
  r.objects = static_cast<std::uint16_t>(t.size());
  int best = -1;
  std::int64_t best_key = 0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    const ObjectEval e = hls::warning::evaluate<Params>(t[i], c);
    if (!e.obstacle) continue;
    ++r.obstacles;
    const std::int64_t judged = e.too_close ? 0 : e.distance_mm;
    const std::int64_t key = (3 - static_cast<int>(e.severity)) * (std::int64_t{1} << 40) + judged;
    if (best < 0 || key < best_key) {
      best = static_cast<int>(i);
      best_key = key;
    }
  }
  if (best < 0) return r;
  const ObjectEval e = hls::warning::evaluate<Params>(t[best], c);
  const Object& o = t[best];
  r.severity = e.severity;
  r.in_tunnel = e.in_tunnel;
  r.too_close = e.too_close;
  r.index = static_cast<std::uint16_t>(best);
  r.distance_mm = e.distance_mm;
  r.closest_x = o.closest_x;
  r.closest_y = o.closest_y;
  r.d_max = o.d_max;
  r.x_min = o.x_min;
  r.x_max = o.x_max;
  r.y_min = o.y_min;
  r.y_max = o.y_max;
  return r;
}

}  // namespace scw::fixtures
