// SPDX-License-Identifier: Apache-2.0
// Runs the streaming disparity model over whole images (no stalls): what the CLI, the golden
// vectors and the real-data checks use to get "our" disparity picture.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <opencv2/core.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "hls/disparity/disparity_params.hpp"
#include "sim/models/disparity_model.hpp"

namespace scw::disparity {

using hls::disparity::DisparityConfig;

/// The CLI's widest frame (the model's line buffers are sized for it; height is unbounded).
constexpr int kHostMaxWidthPx = 2048;
/// Windows N the host builds (compile-time structure of the stage), each with
/// kHostMaxNumDisp candidates in parallel; a range uses dmax - dmin + 1 of them
/// (DisparityConfig::num_disp, a run-time setting of the stage).
constexpr std::array<int, 11> kHostWindows{3, 5, 7, 9, 11, 13, 15, 17, 19, 21, 23};
constexpr int kHostMaxNumDisp = 128;

/// The two named modes of `scw disparity --mode`, `scw run --mode` and `scw sim --mode`.
enum class Mode { thesis, opencv };
/// The one default of all three commands; docs/disparity.md ("The default mode") has the
/// measurements that chose it.
constexpr Mode kDefaultMode = Mode::opencv;
/// The help of `--edge-candidates` (DisparityConfig::edge_candidates), one text for every command.
constexpr const char* kEdgeCandidatesHelp =
    "Left edge band: decide a column whose window fits the right image for only some candidates "
    "among those, when there are at least this many; 0 = only with all (cv::StereoBM: the first "
    "min-disp + candidates - 1 + window/2 columns stay invalid)";
/// "thesis" / "opencv".
const char* mode_name(Mode m);
/// The mode named "thesis" or "opencv"; throws std::invalid_argument naming both otherwise.
Mode mode_from_name(const std::string& name);
/// thesis_mode() or opencv_mode() (cv::StereoBM's defaults) for a frame and dmin.
DisparityConfig mode_config(Mode m, int width, int height, int dmin);

/// Disparity of an 8-bit grey pair (CV_8UC1, same size) with an N x N window (N = window_n)
/// and the candidates dmin .. dmax, through the streaming C++ model at P = 1 (hls::disparity,
/// clocked by sim::DisparityModel, one beat per clock). `options` supplies every field but the
/// geometry: width, height and dmin are taken from the images and `dmin`. Returns CV_16S,
/// disparity x 16 (Q11.4) and invalid_code(options) where invalid, pixel for pixel equal to
/// reference::disparity_reference. Throws std::invalid_argument, saying what is supported,
/// for: empty or non-8-bit-grey images, different sizes, a width above kHostMaxWidthPx, a
/// width or height below the window, dmin < 0, dmax < dmin, an even window, a window outside
/// kHostWindows or more than kHostMaxNumDisp candidates.
cv::Mat disparity_image(const cv::Mat& left, const cv::Mat& right, int window_n, int dmin, int dmax,
                        const DisparityConfig& options);

/// One frame pair, as beats, through the model with no stalls: both inputs offered every
/// cycle, the output always taken. Returns the output beats (one frame per input frame) and
/// the cycles taken in `*cycles` if given; throws std::logic_error if the model stops or flags
/// an error on a well-formed frame. The one loop behind disparity_image and
/// `scw vectors disparity`.
/// run_disparity_model on a stage that may have taken frames before (they leave it ready for
/// the next, as in the pipeline).
template <typename Params>
std::vector<typename Params::disp_beat> run_disparity_frames(
    sim::DisparityModel<Params>& model, const std::vector<typename Params::pixel_beat>& left,
    const std::vector<typename Params::pixel_beat>& right, std::int64_t* cycles = nullptr) {
  auto out = sim::drain_join(model, left, right, left.size(), cycles);
  if (model.kernel().error())
    throw std::logic_error("run_disparity_model: the stage flagged a frame error");
  return out;
}

template <typename Params>
std::vector<typename Params::disp_beat> run_disparity_model(
    const std::vector<typename Params::pixel_beat>& left,
    const std::vector<typename Params::pixel_beat>& right, const DisparityConfig& cfg,
    std::int64_t* cycles = nullptr) {
  if (left.size() != right.size())
    throw std::logic_error("run_disparity_model: left and right have different beat counts");
  using Model = sim::DisparityModel<Params>;
  const auto model = std::make_unique<Model>(cfg);  // line buffers: keep them off the stack
  return run_disparity_frames(*model, left, right, cycles);
}

}  // namespace scw::disparity
