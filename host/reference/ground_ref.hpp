// SPDX-License-Identifier: Apache-2.0
// Whole-map reference for ground removal (plain loops, no line buffer), and the camera-derived
// default configuration.
#pragma once

#include <opencv2/core.hpp>

#include "hls/ground/ground_params.hpp"

namespace scw::reference {

/// Ground removal by its definition (docs/ground.md), written independently of hls::ground: for
/// every pixel (x, y) with y >= 10 and cfg.enable, g[j] = d(x, y - 10 + j), j = 0 .. 10, read as
/// int16; the pixel becomes 0 when every g[j] > 0, every g[j+1] - g[j] >= -cfg.step_tol_q4 and
/// cfg.min_rise_q4 <= g[10] - g[0] <= cfg.max_rise_q4. Every other pixel is copied. `d16` is
/// CV_16SC1 (disparity x 16, invalid 0 or negative) or CV_16UC1 holding the same bit patterns;
/// the result has its type and size. Throws std::invalid_argument for another type or an empty
/// map.
cv::Mat ground_reference(const cv::Mat& d16, const hls::ground::GroundConfig& cfg);

}  // namespace scw::reference

namespace scw::ground {

using hls::ground::GroundConfig;

/// The rise limits a camera implies. On a flat road seen by a rectified camera whose optical
/// axis is parallel to it, a road point at depth Z is f h / Z rows below the horizon and has
/// disparity f b / Z, so the road's disparity grows by b / h px per row, whatever f; over the
/// window's 10 steps by 10 b / h px. Returns enable = true, step_tol 0.25 px (4), min_rise
/// 0.5 x and max_rise 2 x that rise, in Q11.4 rounded to nearest; min_rise is at least 1 so that
/// a surface of constant disparity (an object's face) is never ground. Throws
/// std::invalid_argument if baseline_m or camera_height_m is not a positive finite number, or
/// if max_rise exceeds 32767 (b / h above about 102).
GroundConfig default_ground_config(double baseline_m, double camera_height_m);

}  // namespace scw::ground
