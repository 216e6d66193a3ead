// SPDX-License-Identifier: Apache-2.0
// Disparity maps for the labelling stage's tests and golden vectors (shared fixtures, so they live
// in the product, not in tests/): random fields of many densities and the shapes where one-pass
// labelling goes wrong (spirals, combs, late-merging U shapes, objects across tiles).
#pragma once

#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace scw::fixtures {

/// A w x h map of Q11.4 disparities, row-major.
struct DispMap {
  std::string name;
  int w = 0, h = 0;
  std::vector<std::uint16_t> d;
  std::uint16_t& at(int x, int y) { return d[static_cast<std::size_t>(y * w + x)]; }
};

inline DispMap blank_map(const std::string& name, int w, int h) {
  return DispMap{name, w, h, std::vector<std::uint16_t>(static_cast<std::size_t>(w * h), 0)};
}

/// Sets (x, y) to `d` if it lies inside the map: shapes may run off the edges.
inline void put(DispMap& m, int x, int y, int d) {
  if (x >= 0 && x < m.w && y >= 0 && y < m.h) m.at(x, y) = static_cast<std::uint16_t>(d);
}

/// Each pixel valid with probability `density`, its disparity a smooth field (so neighbours
/// often join) plus noise (so they sometimes do not): joins and splits everywhere.
inline DispMap random_map(int w, int h, double density, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  DispMap m = blank_map("random " + std::to_string(density) + " #" + std::to_string(seed), w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (u01(rng) >= density) continue;
      const int base = 16 * (8 + (x / 9 + 2 * (y / 7)) % 40);
      m.at(x, y) = static_cast<std::uint16_t>(base + static_cast<int>(rng() % 40) - 20);
    }
  return m;
}

/// A square spiral one pixel wide, with gaps of one pixel between its turns: one object whose
/// arms meet only at the centre, reached last.
inline DispMap spiral_map(int w, int h, std::uint16_t d = 320) {
  DispMap m = blank_map("spiral", w, h);
  int x0 = 0, y0 = 0, x1 = w - 1, y1 = h - 1;
  while (x0 <= x1 && y0 <= y1) {
    for (int x = x0; x <= x1; ++x) m.at(x, y0) = d;
    for (int y = y0; y <= y1; ++y) m.at(x1, y) = d;
    if (y1 > y0)
      for (int x = x0; x <= x1; ++x) m.at(x, y1) = d;
    if (x0 + 2 <= x1)
      for (int y = y0 + 2; y <= y1; ++y) m.at(x0, y) = d;
    x0 += 2, y0 += 2, x1 -= 2, y1 -= 2;
    if (x0 <= x1 && y0 <= y1) m.at(x0 - 1, y0) = d;  // the link into the next turn
  }
  return m;
}

/// Teeth hanging from a bar at the bottom (every tooth a separate label until the last row
/// joins them all) and teeth standing on a bar at the top, at alternating disparities. `margin`
/// empty rows above the upper teeth and on either side of the gap between the two combs.
inline DispMap comb_map(int w, int h, int margin = 0) {
  DispMap m = blank_map("comb", w, h);
  const int bar = h / 2 - 1 - margin;  // joins the upper teeth at their foot
  for (int x = 0; x < w; x += 2)
    for (int y = margin; y <= bar; ++y) m.at(x, y) = 400;
  for (int x = 0; x < w; ++x) m.at(x, bar) = 400;
  for (int x = 1; x < w; x += 2)
    for (int y = h / 2 + margin; y < h; ++y)
      m.at(x, y) = static_cast<std::uint16_t>(200 + 4 * (x % 5));
  for (int x = 0; x < w; ++x) m.at(x, h - 1) = 202;
  return m;
}

/// Nested U shapes whose two arms meet only in their bottom rows, each inside the last, with
/// disparities that join within a U and not between neighbouring Us: as many as fit, or the
/// first `count`; the k-th U's disparity is raised by k * `d_step`.
inline DispMap nested_u_map(int w, int h, int count = 0, int d_step = 0) {
  DispMap m = blank_map("nested U", w, h);
  for (int k = 0; 2 * k + 1 < w / 2 && 2 * k + 1 < h && (count == 0 || k < count); ++k) {
    const auto d = static_cast<std::uint16_t>((k % 2 ? 160 : 480) + d_step * k);
    const int xl = 2 * k, xr = w - 1 - 2 * k, yb = h - 1 - 2 * k;
    for (int y = 0; y <= yb; ++y) m.at(xl, y) = m.at(xr, y) = d;
    for (int x = xl; x <= xr; ++x) m.at(x, yb) = d;
  }
  return m;
}

/// A staircase of 2-wide, 3-tall steps from (x0, y0) towards the bottom right, each step sharing
/// an edge with the next (4-connected, crossing every tile border of any grid), plus a frame on
/// the image border at a disparity that does not join it.
inline DispMap staircase_map(int w, int h, int x0 = 0, int y0 = 0) {
  DispMap m = blank_map("staircase", w, h);
  for (int i = 0; x0 + 2 * i < w && y0 + 2 * i < h; ++i)
    for (int dy = 0; dy < 3; ++dy)
      for (int dx = 0; dx < 2; ++dx) put(m, x0 + 2 * i + dx, y0 + 2 * i + dy, 512);
  for (int x = 0; x < w; ++x) m.at(x, 0) = m.at(x, h - 1) = 96;
  for (int y = 0; y < h; ++y) m.at(0, y) = m.at(w - 1, y) = 96;
  return m;
}

/// A grid of lines on every row and column multiple of `step` (a mesh touching every border of
/// tiles of that pitch) at one disparity, and isolated pixels in the cells.
inline DispMap mesh_map(int w, int h, int step) {
  DispMap m = blank_map("mesh " + std::to_string(step), w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (x % step == 0 || y % step == 0) m.at(x, y) = 256;
      if (x % step == step / 2 && y % step == step / 2) m.at(x, y) = 800;
    }
  return m;
}

/// Isolated pixels on a checkerboard of 2 x 2 cells: w * h / 8 one-pixel objects, to exhaust
/// label tables.
inline DispMap dots_map(int w, int h) {
  DispMap m = blank_map("dots", w, h);
  for (int y = 0; y < h; y += 2)
    for (int x = (y / 2) % 2; x < w; x += 2) m.at(x, y) = 300;
  return m;
}

/// Every shape above at one size.
inline std::vector<DispMap> adversarial_maps(int w, int h) {
  return {spiral_map(w, h),  comb_map(w, h),    nested_u_map(w, h), staircase_map(w, h),
          mesh_map(w, h, 8), mesh_map(w, h, 5), dots_map(w, h)};
}

}  // namespace scw::fixtures
