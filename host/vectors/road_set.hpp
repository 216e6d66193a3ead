// SPDX-License-Identifier: Apache-2.0
// Golden vector sets of the road stage: disparity frames back to back in, the C++ model's
// stream out, checked against the floating-point reference (docs/vectors.md, "Road sets").
#pragma once

#include <cstdint>
#include <filesystem>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "hls/road/road_params.hpp"

namespace scw::vectors {

/// The golden-vector build of the road stage: 2 pixels a beat, rows up to 64 px, 48 rows. A
/// replay builds scw_road with these parameters (they are in every set's manifest).
using RoadVecParams = hls::road::RoadParams<2, 64, 48>;

/// What the fit between two frames makes of one frame's gate pixels, in the order
/// hls::road::fit_line tests its rules: the line through them, or the road kept because of
/// the first rule they break.
enum class RoadFit {
  kFitted,     // plausible: the next frame's road
  kFewPixels,  // fewer than min_count pixels in the gate
  kNoSlope,    // the pixels do not rise with the row (den <= 0 or num <= 0)
  kSlope,      // the slope is outside a_min .. a_max (or past 4 px a row)
  kHorizon,    // the horizon row -b / a is above row 0 or outside h_min .. h_max
};
/// "fitted", "few_pixels", "no_slope", "slope", "horizon": the words the roads CSV uses.
const char* road_fit_name(RoadFit f);
/// Which rule fit_line applies to `sums` (RoadFit::kFitted when it returns a new line).
RoadFit road_fit_verdict(const hls::road::FitSums& sums, const hls::road::RoadConfig& cfg);

/// One frame of a sequence and what the fit must make of its pixels.
struct RoadFrame {
  std::string name;
  cv::Mat d;  // CV_16UC1, disparity x 16 (Q11.4), invalid 0 or negative; at most 64 x 48
  RoadFit expect = RoadFit::kFitted;
  bool check_fit = true;  // a user's frame: whatever the rules make of it, as the reference does
};

/// Frames streamed back to back through one stage from reset, and its configuration.
struct RoadSequence {
  std::string preset;
  std::string description;
  hls::road::RoadConfig cfg;
  std::vector<RoadFrame> frames;  // all of one size
  std::string build = "vectors";  // road_builds()
  int ppc = 2;                    // the pipeline builds: 1, 2 or 4 (vectors: 2)
};

/// The builds a set is made at: "vectors" (RoadVecParams; the committed sets) and the pipeline's
/// "small", "tsukuba" and "thesis" (hls/pipeline/pipeline_configs.def) at P = 1, 2 or 4.
const std::vector<std::string>& road_builds();

/// The presets `scw vectors road` writes: "street" and "implausible".
const std::vector<std::string>& road_presets();
/// The sequence of a preset; throws std::invalid_argument naming the presets for another name.
///   street: six frames of fixtures::road_map (64 x 48, road 0.45 px a row, two objects, noise
///     and holes), the horizon pitching between rows 12 and 14, from a nominal road 1.3 times
///     too steep and 4 rows low: every frame's fit is plausible, so the road moves at every sof.
///   implausible: six frames whose fits the plausibility rules refuse, one rule each (a road 3
///     times too steep, one 4 times too flat, a horizon below h_max, one above h_min, one above
///     row 0, a frame of holes with too few pixels): the road stays the nominal one throughout.
RoadSequence road_preset(const std::string& name);

/// Disparity maps of the user's, one a frame (at least 4), sent back to back: 16-bit PNGs of
/// Q11.4 values (`scw disparity --out16`), the one crop of them all (empty: the first map's whole
/// size), and the rig the stage's nominal road comes from (road::rig_setup).
struct UserRoadMaps {
  std::vector<std::filesystem::path> disparity;
  cv::Rect roi;
  double focal_px = 700.0, baseline_m = 0.54;
  double cy_px = -1.0;  // the principal point's row in the whole map (-1: its centre)
  double camera_height_m = 1.2, camera_pitch_deg = 0.0;
  int min_count = 0;  // pixels a fit needs (0: the rig default scaled to the crop, at least 50)
  std::string build = "vectors";
  int ppc = 2;
};
/// The sequence of a user's maps: every frame checked against the reference, whatever its fit.
/// Throws std::invalid_argument naming what does not fit and std::runtime_error for a file that
/// is not a 16-bit map.
RoadSequence road_frames(const UserRoadMaps& maps);

/// What write_road_set() checked and wrote, for the CLI to print.
struct RoadSetSummary {
  int frames = 0, width = 0, height = 0, ppc = 0;
  std::size_t beats = 0;       // per hex file
  std::int64_t cycles = 0;     // the model from reset to the last beat out, no stalls
  int fits = 0;                // fits applied in the stream (a frame's road from the one before)
  long removed = 0;            // pixels the stage set to 0
  long band_edge = 0;          // pixels the model and the reference decide differently, each
                               //   within the kernel's rounding of a band's edge (else throws)
  double road_error_px = 0.0;  // largest distance between the model's road and the reference's
  std::vector<hls::road::Line> roads;  // the road of every frame
  std::vector<RoadFit> verdicts;       // the fit of every frame's pixels
};

/// Streams `seq` through sim::RoadModel (no stalls; and again with idle input and backpressure,
/// which must give the same beats), checks it against hls::road::road_frame and, frame by frame,
/// against reference::road_reference (the pixels removed, the gate's pixel count, the next road
/// to 1/100 px, fitted or kept), and that every frame's fit is the one `seq` expects, then writes
/// the set into `dir`: in.hex, in.png, expected.hex, expected.png, expected_roads.csv and the
/// manifest. Throws std::invalid_argument for a sequence of fewer than 4 frames or frames that
/// do not fit RoadVecParams, std::runtime_error (before writing anything) when a check fails.
RoadSetSummary write_road_set(const RoadSequence& seq, const std::filesystem::path& dir);

}  // namespace scw::vectors
