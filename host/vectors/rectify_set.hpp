// SPDX-License-Identifier: Apache-2.0
// Golden vector sets of the rectify stage: raw pixels and the map in, rectified pixels out, from
// the C++ model and, when the caller brings one, the Verilated stage (docs/vectors.md, "Rectify
// sets").
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "hls/rectify/rectify_params.hpp"
#include "host/rectify/fixed_map.hpp"
#include "sim/core/stall.hpp"
#include "sim/core/stream_check.hpp"

namespace scw::vectors {

/// The golden-vector configuration of the stage: frames up to 128 x 96, a window of 32 raw rows
/// (enough for the chessboard calibration over a 128-px-wide ROI), F = 5 as OpenCV's INTER_BITS.
constexpr int kRectifyVecRows = 32;
template <int P>
using RectifyVecParams = hls::rectify::RectifyParams<P, 128, 96, kRectifyVecRows, 5>;
/// The one beat width a replay's RTL is built with (and the CLI Verilates).
constexpr int kRectifyVecRtlPpc = 2;
using RectifyRtlParams = RectifyVecParams<kRectifyVecRtlPpc>;

/// Frames to rectify with one map: raw images, the map (same size), and which other maps share
/// the lead.
struct RectifyFrame {
  std::vector<cv::Mat> raw;                      // 8UC1, width x height, frames back to back
  std::vector<hls::rectify::MapPoint> map;       // width * height, raster order
  std::vector<scw::rectify::RowWindow> windows;  // every map the stage's lead is planned for
  std::string description;
};

/// The presets `scw vectors rectify` writes: "shift", "rotation", "barrel" (a 64 x 32 test
/// card), "chessboard_left" and "chessboard_right" (a 128 x 96 crop of the bundled pair).
const std::vector<std::string>& rectify_presets();
/// The frame of a preset. The chessboard presets read left01.jpg, right01.jpg and
/// derived_stereo_calibration_helper.yml from `data_dir` and rectify the 128 x 96 output ROI
/// whose top-left is `roi`; both throw std::runtime_error naming what is missing or wrong.
/// Throws std::invalid_argument naming the presets for another name.
/// The chessboard presets' ROI at the vectors build (the committed sets').
inline const cv::Size kRectifyCropSize{128, 96};
/// `size` is the chessboard ROI's (an empty size: the whole image).
RectifyFrame rectify_preset(const std::string& name, const std::filesystem::path& data_dir,
                            cv::Point roi, cv::Size size = kRectifyCropSize);

/// Raw pairs of the user's and their calibration (OpenCV FileStorage M1 D1 M2 D2 R T, as `scw run
/// --calib` reads it); a set is one camera of it.
struct UserCalibratedPair {
  std::vector<std::filesystem::path> left, right;  // a pair a frame
  std::filesystem::path calib;
  bool right_camera = false;
};
/// The frames of one camera of a user's pairs: the rectified ROI at `roi` of `size` (empty: the
/// whole image). Throws std::runtime_error naming the file that is not an image or not the
/// calibration's size, and the ROI that lies outside the image or whose taps span more raw rows
/// or columns than the crop.
RectifyFrame rectify_frame(const UserCalibratedPair& pair, cv::Point roi,
                           cv::Size size = kRectifyCropSize);

/// What an RTL run of the stage at RectifyRtlParams gave: its beats, cycles and trace, and its
/// error bits at the end.
struct RectifyRtlRun {
  sim::RunResult<RectifyRtlParams::pixel_beat> run;
  std::uint8_t err = 0;
};
/// Runs the RTL stage (configured with the given config) on the raw and map beats under a stall
/// pattern until the given number of beats came out. The Verilated model lives with its caller,
/// so the host library does not depend on it.
using RectifyRtl = std::function<RectifyRtlRun(
    const hls::rectify::RectifyConfig&, const std::vector<RectifyRtlParams::pixel_beat>&,
    const std::vector<RectifyRtlParams::map_beat>&, const sim::StallPattern&, std::size_t)>;

/// Throws std::runtime_error, naming the RTL's one build and beat width, unless they are `build`
/// and `ppc`.
void check_rectify_rtl_ppc(int ppc, const std::string& build = "vectors");

/// The builds a set is made at: "vectors" (RectifyVecParams: frames up to 128 x 96, 32 raw rows;
/// the CLI Verilates it) and "thesis" (hls::pipeline::ThesisPipeline's stage: 1280 x 480, 64
/// rows; the C++ model only).
const std::vector<std::string>& rectify_builds();

/// What write_rectify_set() checked and wrote, for the CLI to print.
struct RectifySetSummary {
  int width = 0, height = 0, ppc = 0, frames = 0;
  std::size_t beats = 0;    // output beats, each equal to the integer reference
  std::int64_t cycles = 0;  // the C++ model's run under `stalls`
  std::string stalls;       // the pattern's name
  bool rtl = false;         // the RTL ran too and equalled the model cycle for cycle
  std::size_t rtl_beats = 0;
  int lead_rows = 0, rows_needed = 0, rows = 0;  // rows: the build's raw rows in flight
};

/// Runs `f` through sim::RectifyModel at `ppc` (1, 2 or 4) beats under `stalls` (and through
/// `rtl` when given, which needs ppc = kRectifyVecRtlPpc), checks every beat against the integer
/// reference and the two runs' cycle traces against each other, then writes the set into `dir`:
/// input.png, input.hex, map.hex, expected.hex, expected.png and the manifest. Throws
/// std::runtime_error or std::logic_error (before writing anything) when a check fails;
/// `preset` names the set in the lead planner's messages.
RectifySetSummary write_rectify_set(const RectifyFrame& f, const std::string& preset, int ppc,
                                    const sim::StallPattern& stalls, const RectifyRtl& rtl,
                                    const std::filesystem::path& dir,
                                    const std::string& build = "vectors");

}  // namespace scw::vectors
