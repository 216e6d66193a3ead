// SPDX-License-Identifier: Apache-2.0
// Pictures of the labelling stage's output: coloured label images and object overlays.
#pragma once

#include <opencv2/core.hpp>
#include <vector>

#include "hls/labelling/labelling_params.hpp"

namespace scw::labelling {

/// The colour (BGR) of object number k >= 1: golden-ratio steps round the hue circle, so
/// neighbouring numbers differ strongly and a number keeps its colour from frame to frame and
/// picture to picture. Never black (black is "no object").
cv::Vec3b label_colour(int k);

/// CV_8UC3 picture of a CV_16UC1 label image: 0 black, label k label_colour(k). Throws
/// std::invalid_argument for another type.
cv::Mat colour_labels(const cv::Mat& labels16);

/// CV_8UC3 grey picture of a CV_16UC1 Q11.4 disparity map to draw on: no data (0 or a
/// negative code, >= 0x8000) black, valid values stretched over 64 .. 255 so they stay visible
/// under the overlay.
cv::Mat disparity_picture(const cv::Mat& disp_q4);

/// The inclusive bounding box of an object as a cv::Rect.
cv::Rect box_of(const hls::labelling::Object& o);

/// One object to draw.
struct OverlayItem {
  int number = 0;                  // printed at the box's top left; also picks the colour
  cv::Rect box;                    // drawn as a thin rectangle
  std::vector<cv::Point> outline;  // closed polygon in the item's colour (e.g. a hull); optional
  cv::Mat mask;                    // CV_8UC1 of box.size(), tinted in the item's colour; optional
};

/// A copy of `picture` (CV_8UC1 or CV_8UC3) in colour with each item's mask tinted (half its
/// colour), its outline and box drawn and its number written: an `objects.png`-style view.
cv::Mat draw_overlay(const cv::Mat& picture, const std::vector<OverlayItem>& items);

}  // namespace scw::labelling
