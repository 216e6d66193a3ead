// SPDX-License-Identifier: Apache-2.0
// The map stream as the host builds it: quantised source positions, their row window, and the
// check that a built rectify stage can serve them.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "hls/rectify/rectify_params.hpp"

namespace scw::rectify {

using hls::rectify::MapPoint;

/// One camera's map: for each output pixel (u, v) in raster order, its raw source position in
/// signed fixed point with `frac_bits` fractional bits, clamped to [-S, W*S] x [-S, H*S].
struct FixedMap {
  int width = 0;
  int height = 0;
  int frac_bits = 5;
  std::vector<MapPoint> points;  // width * height, raster order

  const MapPoint& at(int u, int v) const { return points[static_cast<std::size_t>(v) * width + u]; }
};

/// Quantises float maps (CV_32FC1 x and y, as cv::initUndistortRectifyMap writes them) with
/// cvRound(x * 2^F), exactly as cv::convertMaps does, then clamps. Throws std::invalid_argument
/// on mismatched sizes or types.
FixedMap quantise_map(const cv::Mat& map_x, const cv::Mat& map_y, int frac_bits = 5);

/// The same positions as OpenCV's fixed-point map pair for cv::remap: CV_16SC2 integer parts
/// and CV_16UC1 fractional table index (fy * 2^F + fx). Needs frac_bits == 5 (INTER_BITS).
void to_cv_maps(const FixedMap& m, cv::Mat& map_xy, cv::Mat& map_frac);

/// Which raw rows the map needs around each output row v: rows v + dy_min .. v + dy_max (only
/// taps inside the image with nonzero weight count, hls::rectify::decode_taps).
struct RowWindow {
  int dy_min = 0;
  int dy_max = 0;
  bool any = false;  // false if no output pixel touches the image at all
};
RowWindow row_window(const FixedMap& m);

/// How a stage is run for a set of maps (left and right share one lead so both rectified
/// streams leave in step): lead D = max(1, dy_max + 1), and the raw rows in flight that needs,
/// D + 2 - dy_min (the two extra rows are the ones the writer may be filling ahead; see
/// hls::rectify::in_row_window; dy_min = dy_max = 0 when no map touches the image).
struct RectifyPlan {
  int lead_rows = 1;
  int rows_needed = 3;
};
RectifyPlan plan_rows(const std::vector<RowWindow>& windows);

/// Thrown when a map needs more raw rows in flight than the built stage holds; the message
/// names both numbers and what to do.
class MapNotServable : public std::runtime_error {
 public:
  MapNotServable(int rows_needed, int stage_rows, const std::string& what);
  int rows_needed() const { return rows_needed_; }
  int stage_rows() const { return stage_rows_; }

 private:
  int rows_needed_;
  int stage_rows_;
};

/// plan_rows() and the check against a stage built with `stage_rows` rows (throws
/// MapNotServable). `what` names the maps in the message (e.g. the calibration file).
RectifyPlan plan_for_stage(const std::vector<RowWindow>& windows, int stage_rows,
                           const std::string& what);

}  // namespace scw::rectify
