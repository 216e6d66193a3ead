// SPDX-License-Identifier: Apache-2.0
// Knots from a calibration, the reference expansion and its error against the full map.
#include "host/rectify/map_grid.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/calib3d.hpp>
#include <stdexcept>
#include <string>

namespace scw::rectify {
namespace {

/// floor(a / 2^s) for negative a too, without relying on >> of negative numbers.
std::int64_t floor_shift(std::int64_t a, int s) {
  const std::int64_t d = std::int64_t{1} << s;
  return a >= 0 ? a / d : -((-a + d - 1) / d);
}

}  // namespace

int default_knot_bits(int width, int height, int knot_frac_bits) {
  return hls::rectify::knot_bits(std::max(width, height), knot_frac_bits);
}

void extended_float_maps(const cv::Mat& camera, const cv::Mat& dist, const cv::Mat& rot,
                         const cv::Mat& proj, cv::Size image, int grid_log2, cv::Mat& map_x,
                         cv::Mat& map_y) {
  const int g = 1 << grid_log2;
  const cv::Size ext((knot_count(image.width, grid_log2) - 1) * g + 1,
                     (knot_count(image.height, grid_log2) - 1) * g + 1);
  cv::initUndistortRectifyMap(camera, dist, rot, proj, ext, CV_32FC1, map_x, map_y);
}

KnotGrid sample_knots(const cv::Mat& map_x_ext, const cv::Mat& map_y_ext, cv::Size image,
                      int grid_log2, int frac_bits, int knot_frac_bits, int knot_bits) {
  if (grid_log2 < 1 || grid_log2 > 6) throw std::invalid_argument("sample_knots: G must be 2..64");
  if (knot_frac_bits < frac_bits || knot_frac_bits > 12)
    throw std::invalid_argument("sample_knots: knot_frac_bits must be F .. 12");
  KnotGrid g;
  g.width = image.width;
  g.height = image.height;
  g.grid_log2 = grid_log2;
  g.frac_bits = frac_bits;
  g.knot_frac_bits = knot_frac_bits;
  g.knot_bits =
      knot_bits > 0 ? knot_bits : default_knot_bits(image.width, image.height, knot_frac_bits);
  g.cols = knot_count(image.width, grid_log2);
  g.rows = knot_count(image.height, grid_log2);
  const int step = g.grid();
  if (map_x_ext.type() != CV_32FC1 || map_y_ext.type() != CV_32FC1 ||
      map_x_ext.size() != map_y_ext.size() || map_x_ext.cols < (g.cols - 1) * step + 1 ||
      map_x_ext.rows < (g.rows - 1) * step + 1)
    throw std::invalid_argument(
        "sample_knots: need CV_32FC1 maps covering every knot (extended_float_maps)");
  const double lo = -std::ldexp(1.0, g.knot_bits - 1);
  const double hi = std::ldexp(1.0, g.knot_bits - 1) - 1;
  const auto quantise = [&](float v) {
    const double s = static_cast<double>(v) * std::ldexp(1.0, knot_frac_bits);
    if (!(s >= lo) || s > hi) {  // NaN too
      ++g.clamped;
      return static_cast<std::int32_t>(std::isnan(s) || s < lo ? lo : hi);
    }
    return static_cast<std::int32_t>(cvRound(s));
  };
  g.knots.resize(static_cast<std::size_t>(g.cols) * static_cast<std::size_t>(g.rows));
  for (int j = 0; j < g.rows; ++j)
    for (int i = 0; i < g.cols; ++i) {
      KnotPoint& k = g.knots[static_cast<std::size_t>(j) * static_cast<std::size_t>(g.cols) +
                             static_cast<std::size_t>(i)];
      k.x = quantise(map_x_ext.at<float>(j * step, i * step));
      k.y = quantise(map_y_ext.at<float>(j * step, i * step));
    }
  return g;
}

StereoKnots grid_knots(const StereoCalibration& calib, const StereoRectification& rect,
                       int grid_log2, int frac_bits, int knot_frac_bits, int knot_bits) {
  StereoKnots k;
  cv::Mat mx, my;
  extended_float_maps(calib.M1, calib.D1, rect.R1, rect.P1, rect.image_size, grid_log2, mx, my);
  k.left = sample_knots(mx, my, rect.image_size, grid_log2, frac_bits, knot_frac_bits, knot_bits);
  extended_float_maps(calib.M2, calib.D2, rect.R2, rect.P2, rect.image_size, grid_log2, mx, my);
  k.right = sample_knots(mx, my, rect.image_size, grid_log2, frac_bits, knot_frac_bits, knot_bits);
  return k;
}

FixedMap expand(const KnotGrid& g) {
  if (g.knots.size() != static_cast<std::size_t>(g.cols) * static_cast<std::size_t>(g.rows) ||
      g.cols != knot_count(g.width, g.grid_log2) || g.rows != knot_count(g.height, g.grid_log2))
    throw std::invalid_argument("expand: the knot grid does not match its image size");
  FixedMap m;
  m.width = g.width;
  m.height = g.height;
  m.frac_bits = g.frac_bits;
  m.points.resize(static_cast<std::size_t>(g.width) * static_cast<std::size_t>(g.height));
  const std::int64_t G = g.grid();
  const int shift = 2 * g.grid_log2 + g.knot_frac_bits - g.frac_bits;
  const std::int64_t half = std::int64_t{1} << (shift - 1);
  const std::int32_t s = std::int32_t{1} << g.frac_bits;
  for (int v = 0; v < g.height; ++v)
    for (int u = 0; u < g.width; ++u) {
      const int i = u / g.grid(), j = v / g.grid();
      const std::int64_t du = u - i * G, dv = v - j * G;
      const std::int64_t w00 = (G - du) * (G - dv), w10 = du * (G - dv);
      const std::int64_t w01 = (G - du) * dv, w11 = du * dv;
      const KnotPoint &k00 = g.at(i, j), &k10 = g.at(i + 1, j);
      const KnotPoint &k01 = g.at(i, j + 1), &k11 = g.at(i + 1, j + 1);
      const std::int64_t nx = k00.x * w00 + k10.x * w10 + k01.x * w01 + k11.x * w11;
      const std::int64_t ny = k00.y * w00 + k10.y * w10 + k01.y * w01 + k11.y * w11;
      MapPoint& p = m.points[static_cast<std::size_t>(v) * static_cast<std::size_t>(g.width) +
                             static_cast<std::size_t>(u)];
      p.x = static_cast<std::int32_t>(
          std::clamp<std::int64_t>(floor_shift(nx + half, shift), -s, std::int64_t{g.width} * s));
      p.y = static_cast<std::int32_t>(
          std::clamp<std::int64_t>(floor_shift(ny + half, shift), -s, std::int64_t{g.height} * s));
    }
  return m;
}

MapError map_error(const FixedMap& a, const FixedMap& b) {
  if (a.width != b.width || a.height != b.height || a.frac_bits != b.frac_bits ||
      a.points.size() != b.points.size() || a.points.empty())
    throw std::invalid_argument("map_error: the maps differ in size or precision");
  MapError e;
  const double unit = std::ldexp(1.0, -a.frac_bits);
  double sx = 0, sy = 0;
  for (std::size_t n = 0; n < a.points.size(); ++n) {
    const double dx = std::abs(a.points[n].x - b.points[n].x) * unit;
    const double dy = std::abs(a.points[n].y - b.points[n].y) * unit;
    e.max_dx = std::max(e.max_dx, dx);
    e.max_dy = std::max(e.max_dy, dy);
    sx += dx;
    sy += dy;
  }
  e.mean_dx = sx / static_cast<double>(a.points.size());
  e.mean_dy = sy / static_cast<double>(a.points.size());
  return e;
}

Curvature max_curvature(const cv::Mat& map) {
  if (map.type() != CV_32FC1) throw std::invalid_argument("max_curvature: need CV_32FC1");
  Curvature c;
  for (int y = 0; y < map.rows; ++y)
    for (int x = 0; x < map.cols; ++x) {
      const double m = map.at<float>(y, x);
      if (x > 0 && x + 1 < map.cols)
        c.uu = std::max(c.uu, std::abs(static_cast<double>(map.at<float>(y, x - 1)) - 2 * m +
                                       map.at<float>(y, x + 1)));
      if (y > 0 && y + 1 < map.rows)
        c.vv = std::max(c.vv, std::abs(static_cast<double>(map.at<float>(y - 1, x)) - 2 * m +
                                       map.at<float>(y + 1, x)));
    }
  return c;
}

double expansion_error_bound(const Curvature& c, int grid_log2, int frac_bits, int knot_frac_bits) {
  const double g = std::ldexp(1.0, grid_log2);
  return g * g / 8.0 * (c.uu + c.vv) + std::ldexp(1.0, -(knot_frac_bits + 1)) +
         2.0 * std::ldexp(1.0, -(frac_bits + 1));
}

std::int64_t knot_storage_bits(int width, int height, int grid_log2, int knot_bits) {
  return std::int64_t{knot_count(width, grid_log2)} * knot_count(height, grid_log2) * 2 * knot_bits;
}

}  // namespace scw::rectify
