// SPDX-License-Identifier: Apache-2.0
// Quantising OpenCV's float maps into the map stream, and planning the stage's row window.
#include "host/rectify/fixed_map.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "hls/rectify/map_taps.hpp"

namespace scw::rectify {
namespace {

/// cvRound(v * S) clamped to [lo, hi]. Clamping before rounding gives the same result as after
/// (rounding is monotonic and the bounds are integers) and keeps cvRound away from overflow;
/// NaN (no source) goes to lo, outside the image like any clamped position.
std::int32_t quantise(float v, int frac_bits, std::int32_t lo, std::int32_t hi) {
  // v * 2^F is exact in float, as in cv::convertMaps.
  const float s = v * static_cast<float>(1 << frac_bits);
  if (!(s >= static_cast<float>(lo))) return lo;
  if (s >= static_cast<float>(hi)) return hi;
  return cvRound(s);
}

template <int F>
RowWindow row_window_f(const FixedMap& m) {
  RowWindow w;
  for (int v = 0; v < m.height; ++v)
    for (int u = 0; u < m.width; ++u) {
      const auto t = hls::rectify::decode_taps<F>(m.at(u, v), m.width, m.height);
      const auto note = [&](int dy) {
        w.dy_min = w.any ? std::min(w.dy_min, dy) : dy;
        w.dy_max = w.any ? std::max(w.dy_max, dy) : dy;
        w.any = true;
      };
      if (t.row0) note(t.y0 - v);
      if (t.row1) note(t.y0 + 1 - v);
    }
  return w;
}

std::string signed_offset(int d) { return d < 0 ? std::to_string(d) : "+" + std::to_string(d); }

int next_pow2(int n) {
  int p = 4;  // RectifyParams needs Rows >= 4
  while (p < n) p *= 2;
  return p;
}

}  // namespace

FixedMap quantise_map(const cv::Mat& map_x, const cv::Mat& map_y, int frac_bits) {
  if (map_x.type() != CV_32FC1 || map_y.type() != CV_32FC1)
    throw std::invalid_argument(
        "quantise_map: the maps must be CV_32FC1 (as "
        "cv::initUndistortRectifyMap writes with m1type CV_32FC1)");
  if (map_x.size() != map_y.size() || map_x.empty())
    throw std::invalid_argument("quantise_map: map_x and map_y must have the same, non-zero size");
  if (frac_bits < 1 || frac_bits > 8)
    throw std::invalid_argument("quantise_map: frac_bits must be 1..8");
  FixedMap m;
  m.width = map_x.cols;
  m.height = map_x.rows;
  m.frac_bits = frac_bits;
  m.points.resize(static_cast<std::size_t>(m.width) * m.height);
  const std::int32_t s = 1 << frac_bits;
  for (int v = 0; v < m.height; ++v) {
    const float* px = map_x.ptr<float>(v);
    const float* py = map_y.ptr<float>(v);
    for (int u = 0; u < m.width; ++u) {
      MapPoint& p = m.points[static_cast<std::size_t>(v) * m.width + u];
      p.x = quantise(px[u], frac_bits, -s, m.width * s);
      p.y = quantise(py[u], frac_bits, -s, m.height * s);
    }
  }
  return m;
}

void to_cv_maps(const FixedMap& m, cv::Mat& map_xy, cv::Mat& map_frac) {
  if (m.frac_bits != 5)
    throw std::invalid_argument(
        "to_cv_maps: OpenCV's fixed-point maps have 5 fractional bits "
        "(INTER_BITS), this map has " +
        std::to_string(m.frac_bits));
  if (m.points.size() != static_cast<std::size_t>(m.width) * m.height)
    throw std::invalid_argument("to_cv_maps: map has the wrong number of points");
  map_xy.create(m.height, m.width, CV_16SC2);
  map_frac.create(m.height, m.width, CV_16UC1);
  constexpr int kMask = (1 << 5) - 1;
  for (int v = 0; v < m.height; ++v) {
    auto* xy = map_xy.ptr<cv::Vec2s>(v);
    auto* fr = map_frac.ptr<std::uint16_t>(v);
    for (int u = 0; u < m.width; ++u) {
      const MapPoint& p = m.at(u, v);
      xy[u] = cv::Vec2s(static_cast<short>(p.x >> 5), static_cast<short>(p.y >> 5));
      fr[u] = static_cast<std::uint16_t>((p.y & kMask) * (1 << 5) + (p.x & kMask));
    }
  }
}

RowWindow row_window(const FixedMap& m) {
  switch (m.frac_bits) {
    case 1:
      return row_window_f<1>(m);
    case 2:
      return row_window_f<2>(m);
    case 3:
      return row_window_f<3>(m);
    case 4:
      return row_window_f<4>(m);
    case 5:
      return row_window_f<5>(m);
    case 6:
      return row_window_f<6>(m);
    case 7:
      return row_window_f<7>(m);
    case 8:
      return row_window_f<8>(m);
    default:
      throw std::invalid_argument("row_window: frac_bits must be 1..8");
  }
}

RectifyPlan plan_rows(const std::vector<RowWindow>& windows) {
  int dy_max = 0, dy_min = 0;
  bool any = false;
  for (const auto& w : windows) {
    if (!w.any) continue;
    dy_max = any ? std::max(dy_max, w.dy_max) : w.dy_max;
    dy_min = any ? std::min(dy_min, w.dy_min) : w.dy_min;
    any = true;
  }
  RectifyPlan p;
  p.lead_rows = any ? std::max(1, dy_max + 1) : 1;
  // Two rows beyond the lead are the writer's (in_row_window). dy_min > 0 (every tap below row
  // v) needs no fewer rows: the stage's lead is limited to Rows - 1.
  p.rows_needed = p.lead_rows + 2 - std::min(0, any ? dy_min : 0);
  return p;
}

MapNotServable::MapNotServable(int rows_needed, int stage_rows, const std::string& what)
    : std::runtime_error(what + ": the rectification maps need " + std::to_string(rows_needed) +
                         " raw rows in flight, but the rectify stage was built with " +
                         std::to_string(stage_rows) + " rows (RectifyRows); rebuild with " +
                         "RectifyRows >= " + std::to_string(next_pow2(rows_needed)) +
                         " (a power of two), or use a calibration with less distortion/rotation "
                         "(or another stereoRectify alpha: it rescales the rectified view, and "
                         "with it how many raw rows an output row crosses)"),
      rows_needed_(rows_needed),
      stage_rows_(stage_rows) {}

RectifyPlan plan_for_stage(const std::vector<RowWindow>& windows, int stage_rows,
                           const std::string& what) {
  const RectifyPlan p = plan_rows(windows);
  if (p.rows_needed <= stage_rows) return p;
  int dy_min = 0, dy_max = 0;
  bool any = false;
  for (const auto& w : windows)
    if (w.any) {
      dy_min = any ? std::min(dy_min, w.dy_min) : w.dy_min;
      dy_max = any ? std::max(dy_max, w.dy_max) : w.dy_max;
      any = true;
    }
  throw MapNotServable(p.rows_needed, stage_rows,
                       what + " (output row v reads raw rows v" + signed_offset(dy_min) + " .. v" +
                           signed_offset(dy_max) + ")");
}

}  // namespace scw::rectify
