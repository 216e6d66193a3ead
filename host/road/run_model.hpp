// SPDX-License-Identifier: Apache-2.0
// The road stage over a sequence of whole disparity maps (no stalls): what the CLI, the tools
// and the real-data checks use.
#pragma once

#include <opencv2/core.hpp>

#include "hls/road/road.hpp"

namespace scw::road {

using hls::road::RoadConfig;

/// The host's build of the stage: one pixel a beat, rows up to 2048 pixels, 1024 rows.
using HostParams = hls::road::RoadParams<1, 2048, 1024>;

/// Frames in order through one hls::road::Road: each map leaves with the pixels on the road of
/// the frames before it set to 0, and gives the road for the next.
/// 255 where `before` held a valid disparity (positive as int16) that `after` has as 0: the
/// pixels the road stage removed. Both CV_16U or CV_16S of one size.
cv::Mat removed_mask(const cv::Mat& before, const cv::Mat& after);

/// The left image in grey with the pixels `mask` marks tinted green: what the road stage took
/// out, for a person to look at.
cv::Mat road_picture(const cv::Mat& left_grey, const cv::Mat& mask);

class RoadFilter {
 public:
  explicit RoadFilter(const RoadConfig& cfg) : k_(cfg) {}
  /// `q4` is CV_16UC1 (or CV_16SC1), disparity x 16 with invalid 0 or negative; the result has
  /// its type and size. Throws std::invalid_argument for another type or a size beyond
  /// HostParams.
  cv::Mat filter(const cv::Mat& q4);
  /// The road the next frame will be filtered with (before filter() the nominal one; its fit
  /// runs at the next frame's start).
  hls::road::Line next_road() const;
  /// The road the last frame was filtered with.
  const hls::road::Line& road() const { return used_; }

 private:
  hls::road::Road<HostParams> k_;
  hls::road::Line used_{};
};

}  // namespace scw::road
