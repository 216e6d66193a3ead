// SPDX-License-Identifier: Apache-2.0
// Whole-map reference for the road stage in floating point (plain loops, no fixed point).
#pragma once

#include <opencv2/core.hpp>

#include "hls/road/road_params.hpp"

namespace scw::reference {

/// A road in px: d(v) = a v + b.
struct RoadLinePx {
  double a = 0.0, b = 0.0;
};

/// A fixed-point line (code x 2^12) in px.
constexpr RoadLinePx to_px(const hls::road::Line& l) {
  return {l.a / hls::road::kPxUnit, l.b / hls::road::kPxUnit};
}

/// One frame of the road stage by its definition (docs/road.md), written independently of
/// hls::road in doubles: `road` is the frame's road; `kept` the map without the pixels within
/// tol + tol_rel d_road of it (rows where d_road >= 1 px, cfg.enable); `next` the least-squares
/// line through the pixels within gate + gate_rel d_road, or `road` when it is not plausible
/// (fewer than min_count pixels, a slope outside a_min .. a_max, a horizon outside h_min ..
/// h_max). The tolerances are the configuration's quantised values. `q4` is CV_16UC1 or
/// CV_16SC1, disparity x 16, invalid 0 or negative.
struct RoadFrameRef {
  cv::Mat kept;
  RoadLinePx next;
  bool fitted = false;
  double pixels = 0;  // in the gate
};
RoadFrameRef road_reference(const cv::Mat& q4, const RoadLinePx& road,
                            const hls::road::RoadConfig& cfg);

}  // namespace scw::reference
