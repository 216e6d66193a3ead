// SPDX-License-Identifier: Apache-2.0
// Grid-compressed maps on the host: knots from a calibration, the expansion as plain loops
// (the reference the kernel and RTL are checked against), and its error against the full map.
#pragma once

#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "hls/rectify/map_grid.hpp"
#include "host/rectify/calibration.hpp"
#include "host/rectify/fixed_map.hpp"

namespace scw::rectify {

using hls::rectify::KnotPoint;

/// Knots of one camera's map every G = 2^grid_log2 pixels for a width x height image: knot
/// (i, j) is the source position of output pixel (i G, j G), signed fixed point with
/// knot_frac_bits fractional bits, i = 0 .. cols - 1, j = 0 .. rows - 1.
struct KnotGrid {
  int width = 0;
  int height = 0;
  int grid_log2 = 4;
  int frac_bits = 5;             // of the expanded map (F)
  int knot_frac_bits = 7;        // of the knots
  int knot_bits = 0;             // signed width knots were clamped to
  int cols = 0, rows = 0;        // ((width - 1) >> k) + 2, ((height - 1) >> k) + 2
  int clamped = 0;               // knots that did not fit knot_bits (0 on any sane calibration)
  std::vector<KnotPoint> knots;  // rows x cols, row-major

  int grid() const { return 1 << grid_log2; }
  const KnotPoint& at(int i, int j) const {
    return knots[static_cast<std::size_t>(j) * static_cast<std::size_t>(cols) +
                 static_cast<std::size_t>(i)];
  }
};

/// Knot columns (rows) for `pixels` pixels at G = 2^grid_log2 (the block's own count).
using hls::rectify::knot_count;

/// The knot width the block uses for images up to max(width, height) (MapGridParams::kKnotBits).
int default_knot_bits(int width, int height, int knot_frac_bits);

/// cv::initUndistortRectifyMap (CV_32FC1) of one camera on the image extended to cover every
/// knot: ((cols - 1) G + 1) x ((rows - 1) G + 1) pixels, the same camera matrices, so pixels
/// beyond the image continue the map smoothly.
void extended_float_maps(const cv::Mat& camera, const cv::Mat& dist, const cv::Mat& rot,
                         const cv::Mat& proj, cv::Size image, int grid_log2, cv::Mat& map_x,
                         cv::Mat& map_y);

/// Samples extended float maps at the knots and quantises with cvRound(x 2^FK), clamped to the
/// signed knot_bits range (knot_bits 0: default_knot_bits).
KnotGrid sample_knots(const cv::Mat& map_x_ext, const cv::Mat& map_y_ext, cv::Size image,
                      int grid_log2, int frac_bits = 5, int knot_frac_bits = 7, int knot_bits = 0);

/// Both cameras' knots from a calibration and its rectification (R1/P1, R2/P2).
struct StereoKnots {
  KnotGrid left, right;
};
StereoKnots grid_knots(const StereoCalibration& calib, const StereoRectification& rect,
                       int grid_log2, int frac_bits = 5, int knot_frac_bits = 7, int knot_bits = 0);

/// The expanded map, straight from the weights (plain loops, 64-bit, explicit floor; it shares
/// no code with hls::rectify::MapGrid):
///   m = floor((K00 (G-du)(G-dv) + K10 du (G-dv) + K01 (G-du) dv + K11 du dv + 2^(s-1)) / 2^s),
///   s = 2k + knot_frac_bits - F, then clamped to [-S, W S] x [-S, H S] as quantise_map does.
FixedMap expand(const KnotGrid& g);

/// |a - b| per coordinate in pixels over all points (same size and F required).
struct MapError {
  double max_dx = 0, max_dy = 0;
  double mean_dx = 0, mean_dy = 0;
  double max() const { return max_dx > max_dy ? max_dx : max_dy; }
};
MapError map_error(const FixedMap& a, const FixedMap& b);

/// Largest |second difference| of a float map along u and along v (pixel spacing), an estimate
/// of max |d2m/du2| and max |d2m/dv2| over the extended image.
struct Curvature {
  double uu = 0, vv = 0;
};
Curvature max_curvature(const cv::Mat& map);

/// What the expansion may differ from the full quantised map by, in pixels, for one coordinate:
/// bilinear interpolation of a C2 function over G x G cells errs by at most
/// G^2/8 (max|m_uu| + max|m_vv|); knot rounding adds at most 2^-(FK+1), the expansion's own
/// rounding 2^-(F+1) and the full map's rounding 2^-(F+1); clamping both to the same box only
/// shrinks differences.
double expansion_error_bound(const Curvature& c, int grid_log2, int frac_bits, int knot_frac_bits);

/// On-chip knot storage in bits: knots x 2 coordinates x knot bits (what the four RAMs hold,
/// before rounding each up to a power-of-two depth).
std::int64_t knot_storage_bits(int width, int height, int grid_log2, int knot_bits);

}  // namespace scw::rectify
