// SPDX-License-Identifier: Apache-2.0
// Whole-image labelling reference: flood fill with an explicit stack, then straight sums.
#include "host/reference/labelling_ref.hpp"

#include <algorithm>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>

namespace scw::reference {
namespace {

using hls::labelling::disp_t;
using hls::labelling::Object;

constexpr int kUnvisited = -1;

// The descriptor of one component from its pixel indices, sorted in raster order first so that
// "first pixel" and "first pixel holding d_max" are plain scans.
Object describe(std::vector<std::size_t>& pixels, const disp_t* disp, int width) {
  std::sort(pixels.begin(), pixels.end());
  Object o;
  o.area = static_cast<std::uint32_t>(pixels.size());
  o.first_x = static_cast<std::uint16_t>(pixels.front() % static_cast<std::size_t>(width));
  o.first_y = static_cast<std::uint16_t>(pixels.front() / static_cast<std::size_t>(width));
  o.x_min = o.x_max = o.first_x;
  o.y_min = o.y_max = o.first_y;
  o.d_min = o.d_max = disp[pixels.front()];
  for (const std::size_t i : pixels) {
    const std::uint16_t x = static_cast<std::uint16_t>(i % static_cast<std::size_t>(width));
    const std::uint16_t y = static_cast<std::uint16_t>(i / static_cast<std::size_t>(width));
    o.x_min = std::min(o.x_min, x);
    o.x_max = std::max(o.x_max, x);
    o.y_min = std::min(o.y_min, y);
    o.y_max = std::max(o.y_max, y);
    o.d_min = std::min(o.d_min, disp[i]);
    o.d_max = std::max(o.d_max, disp[i]);
    const std::uint64_t u = x, v = y;
    o.m10 += u;
    o.m01 += v;
    o.m20 += u * u;
    o.m11 += u * v;
    o.m02 += v * v;
    o.m30 += u * u * u;
    o.m21 += u * u * v;
    o.m12 += u * v * v;
    o.m03 += v * v * v;
    o.sum_d += disp[i];
    o.sum_dd += std::uint64_t{disp[i]} * disp[i];
  }
  // Raster order: the first pixel found holding d_max is the closest point.
  for (const std::size_t i : pixels)
    if (disp[i] == o.d_max) {
      o.closest_x = static_cast<std::uint16_t>(i % static_cast<std::size_t>(width));
      o.closest_y = static_cast<std::uint16_t>(i / static_cast<std::size_t>(width));
      break;
    }
  return o;
}

}  // namespace

LabellingReference labelling_reference(const std::uint16_t* disp, int width, int height,
                                       const hls::labelling::LabellingConfig& cfg) {
  if (disp == nullptr) throw std::invalid_argument("labelling_reference: the map is null");
  // Coordinates travel in 16 bits in the Object, as they do in the stage.
  constexpr int kMaxSide = 65535;
  if (width < 1 || height < 1 || width > kMaxSide || height > kMaxSide)
    throw std::invalid_argument("labelling_reference: the map is " + std::to_string(width) + " x " +
                                std::to_string(height) + " px; each side must be 1 .. 65535");

  const std::size_t w = static_cast<std::size_t>(width);
  const std::size_t n = w * static_cast<std::size_t>(height);
  const auto valid = [&](std::size_t i) { return hls::labelling::is_valid(disp[i], cfg); };

  // Component of every pixel (kUnvisited for background too), then each component's pixels.
  std::vector<int> comp(n, kUnvisited);
  std::vector<std::vector<std::size_t>> members;
  std::vector<std::size_t> stack;
  for (std::size_t seed = 0; seed < n; ++seed) {
    if (comp[seed] != kUnvisited || !valid(seed)) continue;
    // Scanning seeds in raster order makes every seed its component's first pixel, so the
    // components come out numbered in raster order of their first pixel.
    const int id = static_cast<int>(members.size());
    members.emplace_back();
    comp[seed] = id;
    stack.assign(1, seed);
    while (!stack.empty()) {
      const std::size_t p = stack.back();
      stack.pop_back();
      members.back().push_back(p);
      const std::size_t x = p % w;
      // Each edge names its later pixel first: for left and up the later pixel is p.
      const auto visit = [&](std::size_t q, disp_t later, disp_t earlier) {
        if (comp[q] == kUnvisited && valid(q) && hls::labelling::joins(later, earlier)) {
          comp[q] = id;
          stack.push_back(q);
        }
      };
      if (x > 0) visit(p - 1, disp[p], disp[p - 1]);
      if (x + 1 < w) visit(p + 1, disp[p + 1], disp[p]);
      if (p >= w) visit(p - w, disp[p], disp[p - w]);
      if (p + w < n) visit(p + w, disp[p + w], disp[p]);
    }
  }

  LabellingReference out;
  out.components = static_cast<int>(members.size());
  out.labels.assign(n, 0);
  for (auto& pixels : members) {
    if (pixels.size() < static_cast<std::size_t>(std::max(cfg.min_area, 0))) continue;
    if (out.objects.size() >= std::numeric_limits<std::uint16_t>::max())
      throw std::overflow_error(
          "labelling_reference: more than 65535 objects reach min_area; the 16-bit label image "
          "cannot number them");
    out.objects.push_back(describe(pixels, disp, width));
    const auto label = static_cast<std::uint16_t>(out.objects.size());
    for (const std::size_t i : pixels) out.labels[i] = label;
  }
  return out;
}

}  // namespace scw::reference
