// SPDX-License-Identifier: Apache-2.0
// The pipeline in floating point and plain references, for checking the stages' chain end to
// end: cv::StereoBM, flood-fill labelling, the Eigen warning reference.
#pragma once

#include <string>
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

/// The same chain over a sequence of pairs: each frame filtered with the road the frame before
/// fitted (the first with the nominal road), as the road stage carries it from frame to frame.
class ReferenceChain {
 public:
  ReferenceChain(int window_n, const StageOptions& opt);
  ReferenceFrame next(const cv::Mat& left, const cv::Mat& right);

 private:
  int window_n_;
  StageOptions opt_;
  bool started_ = false;
  reference::RoadLinePx road_{};
};

/// "" when the pipeline's frame result `got` is the reference's `ref` (objects, obstacles,
/// severity, the deciding object's closest point, largest disparity and box; the distance within
/// host::warning::distance_tolerance_m), else what differs, e.g. "objects 3 (reference 4)".
/// `w` x `h` and `opt` are the frame's.
std::string reference_mismatch(const hls::warning::FrameResult& got, const ReferenceFrame& ref,
                               int w, int h, const StageOptions& opt);
/// Where the stage's fixed point and the reference's doubles may decide an object differently,
/// by the warning stage's documented accuracy (docs/warning.md): its height (or height above the
/// road) within 1 cm of min_height, its rule disparity within one Q11.4 code (1/16 px) of the
/// 1 px that makes it measurable, its gap within 1 cm of the tunnel or of `near`, its judged
/// distance within the distance tolerance of `high` or `medium`. "" when no object of `ref` is
/// that close to a decision, else which and why, e.g. "object 3: height 0.4983 m, min 0.5 m".
/// A frame whose obstacles or severity differ from the reference only through such an object
/// is a boundary case, not a mismatch.
std::string decision_boundary(const ReferenceFrame& ref, int w, int h, const StageOptions& opt);

/// "" when a frame's object words `objects` are the reference's objects (as sets: the stage
/// lists them by root node, the reference by first pixel), else how they differ.
std::string object_mismatch(std::vector<hls::labelling::Object> objects, const ReferenceFrame& ref);

}  // namespace scw::host::pipeline
