// SPDX-License-Identifier: Apache-2.0
// The pipeline in floating point and plain references, for checking the stages' chain end to
// end: cv::StereoBM, flood-fill labelling, the Eigen warning reference.
#pragma once

#include <vector>

#include <opencv2/core.hpp>

#include "hls/labelling/labelling_params.hpp"
#include "host/pipeline/setup.hpp"
#include "host/reference/road_ref.hpp"
#include "host/warning/reference.hpp"

namespace scw::host::pipeline {

struct ReferenceFrame {
  cv::Mat disparity;  // CV_16S, Q11.4, after the road reference when opt.road
  reference::RoadLinePx road;  // the road this frame was filtered with
  std::vector<hls::labelling::Object> objects;  // flood fill, raster order of first pixel
  host::warning::RefFrame result;               // Eigen, metres
};

/// A rectified 8-bit pair through cv::StereoBM (opencv mode only: its options are the stage's;
/// a range that is not a multiple of 16 candidates goes through the direct reference
/// reference::disparity_reference instead), the road reference (when opt.road), the flood-fill
/// reference and the Eigen warning reference, with `opt`'s settings. The window is `window_n`.
/// The pair is taken as the `frames`-th of a run of that same pair, so the road reference runs
/// `frames` times from the nominal road, each frame's fit the next one's road, as the stage
/// does. Throws std::invalid_argument for thesis mode.
ReferenceFrame reference_frame(const cv::Mat& left, const cv::Mat& right, int window_n,
                               const StageOptions& opt, int frames = 1);

}  // namespace scw::host::pipeline
