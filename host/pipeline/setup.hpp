// SPDX-License-Identifier: Apache-2.0
// From what a user sets (mode, disparity range, tiles, camera and car) to a pipeline run's
// settings, the knots of an identity map for rectified input, and a pair as pixel beats.
#pragma once

#include <vector>

#include <opencv2/core.hpp>

#include "hls/common/beat.hpp"
#include "host/disparity/run_model.hpp"
#include "host/rectify/map_grid.hpp"
#include "host/road/setup.hpp"
#include "host/warning/setup.hpp"
#include "sim/core/frame_beats.hpp"
#include "sim/pipeline/pipeline_setup.hpp"

namespace scw::host::pipeline {

/// The stages' settings that do not come from the build.
struct StageOptions {
  disparity::Mode mode = disparity::kDefaultMode;
  int edge_candidates = 0;  // DisparityConfig::edge_candidates (0: the mode's blind left band)
  int dmin = 0;
  int num_disp = 16;  // candidates dmin .. dmin + num_disp - 1
  int tiles_x = 2, tiles_y = 2;
  int min_area = 50;
  host::warning::WarningSetup warning;  // principal point and d_limit are set from the frame
  bool road = true;              // the road stage removes the road (off: it passes everything)
  double camera_height_m = 1.2;  // the road stage's nominal road
  double camera_pitch_deg = 0.0;  //   and its horizon (down is positive)
  int road_min_count = road::RoadSetup{}.min_count;  // pixels the road stage's fit needs
};

/// The settings the small build's runs use (its tests, `scw soak`): opencv mode, disparities
/// 0 .. 15, 2 x 2 tiles, objects of 20 px, a camera of f 100 px and b 0.2 m.
StageOptions small_build_options();

/// Knots of the map that leaves an image as it is (rectified input): knot (i, j) at pixel
/// (i G, j G), G = 2^grid_log2.
std::vector<hls::rectify::KnotPoint> identity_knots(int width, int height, int grid_log2);

/// A run's settings: `opt` for a width x height frame, both cameras' knots and the rectifiers'
/// lead. The warning setup's principal point defaults to the frame's centre when it is 0, its
/// d_limit to the top of the disparity range; the labelling floor is the disparity stage's
/// invalid code when that is above 0 (opencv mode with dmin > 0). Throws std::invalid_argument
/// for values a stage cannot take.
sim::PipelineSetup make_setup(int width, int height, int grid_log2, const StageOptions& opt,
                              std::vector<hls::rectify::KnotPoint> left_knots,
                              std::vector<hls::rectify::KnotPoint> right_knots, int lead_rows);

/// The warning setup make_setup uses (principal point and d_limit filled in).
host::warning::WarningSetup warning_setup(int width, int height, const StageOptions& opt);

/// Frames of one camera back to back as beats of P pixels.
template <int P>
std::vector<hls::Beat<std::uint8_t, P>> frames_beats(const std::vector<cv::Mat>& frames) {
  std::vector<hls::Beat<std::uint8_t, P>> v;
  for (const cv::Mat& f : frames) {
    const cv::Mat c = f.isContinuous() ? f : f.clone();
    const auto b = sim::frame_beats<P>(c.ptr<std::uint8_t>(), c.cols, c.rows);
    v.insert(v.end(), b.begin(), b.end());
  }
  return v;
}

}  // namespace scw::host::pipeline
