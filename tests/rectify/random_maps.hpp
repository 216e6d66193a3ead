// SPDX-License-Identifier: Apache-2.0
// Map generators for rectify tests and golden vectors: smooth warps (shift, rotation, barrel)
// and seeded random maps that a stage with a given row window can serve.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "hls/rectify/map_taps.hpp"
#include "hls/rectify/rectify_params.hpp"
#include "host/rectify/test_maps.hpp"

namespace scw::test {

using hls::rectify::MapPoint;

// The smooth warps and the host's quantisation live in host/ (`scw vectors rectify` uses them).
using rectify::barrel_map;
using rectify::clamp_point;
using rectify::quantise_point;
using rectify::rotation_map;
using rectify::shift_map;

namespace detail {

template <int F>
bool point_in_window(const MapPoint& p, int v, int width, int height, int lead_rows,
                     int stage_rows) {
  const auto t = hls::rectify::decode_taps<F>(p, width, height);
  if (t.row0 && !hls::rectify::in_row_window(t.y0 - v, lead_rows, stage_rows)) return false;
  if (t.row1 && !hls::rectify::in_row_window(t.y0 + 1 - v, lead_rows, stage_rows)) return false;
  return true;
}

}  // namespace detail

/// Whether output row v's point only needs raw rows inside the window of a stage with
/// `stage_rows` rows and lead D = `lead_rows` (hls::rectify::decode_taps and in_row_window).
inline bool point_in_window(const MapPoint& p, int v, int width, int height, int frac_bits,
                            int lead_rows, int stage_rows) {
  switch (frac_bits) {
    case 1: return detail::point_in_window<1>(p, v, width, height, lead_rows, stage_rows);
    case 2: return detail::point_in_window<2>(p, v, width, height, lead_rows, stage_rows);
    case 3: return detail::point_in_window<3>(p, v, width, height, lead_rows, stage_rows);
    case 4: return detail::point_in_window<4>(p, v, width, height, lead_rows, stage_rows);
    case 5: return detail::point_in_window<5>(p, v, width, height, lead_rows, stage_rows);
    case 6: return detail::point_in_window<6>(p, v, width, height, lead_rows, stage_rows);
    case 7: return detail::point_in_window<7>(p, v, width, height, lead_rows, stage_rows);
    case 8: return detail::point_in_window<8>(p, v, width, height, lead_rows, stage_rows);
    default: throw std::invalid_argument("frac_bits must be 1..8");
  }
}

/// Whole-map version of point_in_window (a map of width x height output pixels, raster order).
inline bool map_in_window(const std::vector<MapPoint>& m, int width, int height, int frac_bits,
                          int lead_rows, int stage_rows) {
  for (int v = 0; v < height; ++v)
    for (int u = 0; u < width; ++u)
      if (!point_in_window(m[static_cast<std::size_t>(v) * width + u], v, width, height,
                           frac_bits, lead_rows, stage_rows))
        return false;
  return true;
}

/// A seeded random map of width x height points (frac_bits fractional bits, clamped as the host
/// does) that a stage with `stage_rows` raw rows and lead D = `lead_rows` can serve: every raw
/// row a point needs lies in the window hls::rectify::in_row_window allows (today
/// v + D - stage_rows + 2 .. v + D - 1). It mixes a smooth warp
/// (shift, small rotation or barrel/pincushion, vertically placed in the window) with random
/// jitter and special points: fully outside the image on every side, partly outside (x = -S + 1
/// .., (W-1)*S + fraction), exact integers, fraction S - 1, and uniformly random positions.
/// Points the warp or jitter push outside the window are clamped vertically onto its edge.
inline std::vector<MapPoint> random_map(int width, int height, int frac_bits, int lead_rows,
                                        int stage_rows, std::uint64_t seed) {
  if (lead_rows < 1 || lead_rows > stage_rows - 1)
    throw std::invalid_argument("random_map: lead_rows must be 1 .. stage_rows - 1");
  std::mt19937_64 rng(seed);
  const auto uni = [&](double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(rng);
  };
  const auto pick = [&](int n) { return static_cast<int>(rng() % static_cast<unsigned>(n)); };
  const std::int32_t s = std::int32_t{1} << frac_bits;
  // The window relative to v, taken from in_row_window itself so the two cannot disagree
  // (today v + D - stage_rows + 2 .. v + D - 1).
  int lo = stage_rows, hi = -stage_rows - 2;
  for (int dy = -stage_rows - 2; dy <= stage_rows; ++dy)
    if (hls::rectify::in_row_window(dy, lead_rows, stage_rows)) {
      lo = std::min(lo, dy);
      hi = std::max(hi, dy);
    }
  if (lo > hi) throw std::invalid_argument("random_map: empty row window");
  const double mid = (lo + hi) / 2.0, half = (hi - lo) / 2.0;
  const double cx = (width - 1) / 2.0, cy = (height - 1) / 2.0;

  // The smooth part: a warp whose vertical displacement mostly fits the window.
  const int kind = pick(3);
  const double dx = uni(-0.25, 0.25) * width;
  const double dy = mid + uni(-1.0, 1.0) * half;
  const double max_angle = std::asin(std::min(1.0, 2.0 * half / std::max(1, width)));
  const double angle = uni(-1.0, 1.0) * max_angle;
  const double ca = std::cos(angle), sa = std::sin(angle);
  const double k1 = uni(-0.3, 0.3);
  const double r2n = std::max(1.0, cx * cx + cy * cy);
  const double jitter_p = uni(0.0, 0.5), special_p = uni(0.02, 0.2);

  std::vector<MapPoint> m(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  for (int v = 0; v < height; ++v)
    for (int u = 0; u < width; ++u) {
      double x = u, y = v;
      if (kind == 0) {
        x += dx;
        y += dy;
      } else if (kind == 1) {
        x = cx + ca * (u - cx) - sa * (v - cy) + dx * 0.1;
        y = cy + sa * (u - cx) + ca * (v - cy) + mid;
      } else {
        const double f = 1.0 + k1 * ((u - cx) * (u - cx) + (v - cy) * (v - cy)) / r2n;
        x = cx + (u - cx) * f;
        y = cy + (v - cy) * f + mid;
      }
      if (uni(0.0, 1.0) < jitter_p) {
        x += uni(-1.5, 1.5);
        y += uni(-1.5, 1.5);
      }
      MapPoint p = quantise_point(x, y, width, height, frac_bits);
      if (uni(0.0, 1.0) < special_p) {
        const std::int32_t frac = static_cast<std::int32_t>(rng() % static_cast<unsigned>(s));
        switch (pick(12)) {
          case 0: p.x = -s * (1 + pick(3)); break;                      // fully left
          case 1: p.x = (width + pick(3)) * s + frac; break;            // fully right
          case 2: p.y = -s * (1 + pick(3)); break;                      // fully above
          case 3: p.y = (height + pick(3)) * s + frac; break;           // fully below
          case 4: p.x = -s + 1 + pick(s - 1 > 0 ? s - 1 : 1); break;     // partly left
          case 5: p.x = (width - 1) * s + frac; break;                  // partly right
          case 6: p.y = -s + 1 + pick(s - 1 > 0 ? s - 1 : 1); break;     // partly above
          case 7: p.y = (height - 1) * s + frac; break;                 // partly below
          case 8: p.x &= ~(s - 1); p.y &= ~(s - 1); break;              // exact integers
          case 9: p.x |= s - 1; p.y |= s - 1; break;                    // fraction S - 1
          case 10: p.y &= ~(s - 1); p.x |= s - 1; break;                // mixed
          default:                                                      // anywhere
            p.x = static_cast<std::int32_t>(uni(-2.0 * s, (width + 1.0) * s));
            p.y = static_cast<std::int32_t>(uni(-2.0 * s, (height + 1.0) * s));
        }
        p = clamp_point(p, width, height, frac_bits);
      }
      if (!point_in_window(p, v, width, height, frac_bits, lead_rows, stage_rows)) {
        // Rows v + lo .. v + hi hold every tap of y in [(v + lo) S, (v + hi) S]; where that
        // range leaves the image, -S and H * S need no rows at all.
        p.y = std::clamp(p.y, std::clamp((v + lo) * s, -s, height * s),
                         std::clamp((v + hi) * s, -s, height * s));
        if (!point_in_window(p, v, width, height, frac_bits, lead_rows, stage_rows))
          throw std::logic_error("random_map: clamped point outside the row window at v = " +
                                 std::to_string(v) + ", y = " + std::to_string(p.y));
      }
      m[static_cast<std::size_t>(v) * width + u] = p;
    }
  return m;
}

}  // namespace scw::test
