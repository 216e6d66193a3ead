// SPDX-License-Identifier: Apache-2.0
// A stereo calibration as cv::stereoCalibrate writes it, and the rectification built from it.
#pragma once

#include <opencv2/core.hpp>
#include <string>

namespace scw::rectify {

/// Intrinsics and extrinsics of a stereo pair, all CV_64F: M1, M2 3x3 camera matrices, D1, D2
/// distortion vectors of 4, 5, 8, 12 or 14 coefficients (1 x N), R 3x3 and T 3x1 taking points
/// from the left camera's frame to the right one's (cv::stereoCalibrate's convention).
struct StereoCalibration {
  cv::Size image_size;
  cv::Mat M1, D1, M2, D2, R, T;
  std::string source;  // file it was read from, for messages
};

/// Reads M1 D1 M2 D2 R T from an OpenCV FileStorage file (YAML, XML or JSON, as OpenCV's
/// stereo_calib sample or cv::FileStorage << writes it). The image size comes from the
/// `image_width` / `image_height` nodes when present, else from `fallback_size` (e.g. the
/// size of the images to rectify). Throws std::runtime_error naming the file, the bad node,
/// the expected shape and how to fix it.
StereoCalibration load_stereo_calibration(const std::string& path, cv::Size fallback_size = {});

/// stereoRectify's alpha. -1 keeps the calibrated focal length (no rescaling), so P1, P2 and Q
/// are those OpenCV's stereo_calib sample computes and later stages see the calibration's own
/// f; on the bundled chessboard calibration it needs 81 of the host stage's 128 raw rows. 0 .. 1
/// rescales from "valid pixels only" to "every raw pixel kept", which changes the rows needed
/// (measured 68 at 0, 41 at 0.5, 70 at 1) at the cost of resolution; see docs/rectify.md.
constexpr double kDefaultAlpha = -1.0;

/// Rectifying transforms and per-camera float maps of one calibration.
struct StereoRectification {
  cv::Size image_size;
  double alpha = kDefaultAlpha;
  cv::Mat R1, R2;           // 3x3 rectifying rotations
  cv::Mat P1, P2;           // 3x4 projections in the rectified frame: P2(0, 3) = -f * baseline
  cv::Mat Q;                // 4x4 disparity-to-depth matrix
  cv::Rect roi1, roi2;      // all-valid rectangles (cv::stereoRectify)
  cv::Mat map1_x, map1_y;   // left: CV_32FC1 raw x, y for each rectified pixel
  cv::Mat map2_x, map2_y;   // right
  double focal_px() const;  // f of the rectified cameras, pixels
  double baseline() const;  // |T| along the rectified x axis, calibration units
  cv::Point2d principal_point() const;  // (cx, cy) of the rectified left camera, pixels
};

/// cv::stereoRectify (CALIB_ZERO_DISPARITY, so both rectified cameras share cx and a point at
/// infinity has disparity 0) and cv::initUndistortRectifyMap (CV_32FC1) for both cameras.
StereoRectification rectify_calibration(const StereoCalibration& calib,
                                        double alpha = kDefaultAlpha);

}  // namespace scw::rectify
