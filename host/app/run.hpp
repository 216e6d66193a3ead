// SPDX-License-Identifier: Apache-2.0
// The whole chain on one stereo pair: rectify, disparity, (ground removal,) labelling and
// warning through the stages' C++ models, then the application layer; what `scw run` drives.
#pragma once

#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

#include "hls/labelling/labelling_params.hpp"
#include "hls/warning/warning_params.hpp"
#include "host/disparity/run_model.hpp"
#include "host/labelling/run_model.hpp"
#include "host/rectify/fixed_map.hpp"
#include "host/rectify/run_model.hpp"
#include "host/road/run_model.hpp"
#include "host/warning/setup.hpp"

namespace scw::app {

/// Every setting of the chain. Defaults: the settings docs/warning.md measured on the street
/// pair (window 21, d 0 .. 127, 4 x 4 tiles, 200 px objects, no ground removal, a 0.5 m minimum
/// height; it measured opencv mode) and the disparity mode every command defaults to
/// (disparity::kDefaultMode, docs/disparity.md).
struct RunOptions {
  int window = 21;
  int min_disp = 0;
  int max_disp = 127;
  disparity::Mode mode = disparity::kDefaultMode;
  // DisparityConfig::edge_candidates: the left edge band decided from 8 candidates on
  // (docs/disparity.md, "The left edge band": chosen on Aloe).
  int edge_candidates = 8;
  int tiles_x = 4, tiles_y = 4;
  int min_area = 200;
  bool road = true;     // the road stage (docs/road.md) between disparity and labelling
  bool ground = false;  // thesis 6.2 ground-plane removal after it
  double camera_height_m = 1.2;  // the road stage's nominal road, the ground filter's slope
  double camera_pitch_deg = 0.0;  // the road stage's nominal horizon (down is positive)
  host::warning::WarningSetup warning;  // camera, car, thresholds (principal point, limit set
                                        // by the runner from the images and max_disp)
  std::string classifier;  // model file from `scw train`; empty: the parallelepiped classifier
  double classifier_s = 2.0;
  bool kalman = false;
  double frame_period_s = 0.01;  // 100 Hz
  bool overlay_on_labels = false;  // draw the overlay on the label picture, not the left image
};

/// Rectification of raw pairs: the quantised maps of both cameras and the plan's lead rows.
struct RectifyMaps {
  rectify::FixedMap left, right;
  int lead_rows = 0;
};

/// One object of a frame, with what the application layer made of it.
struct ObjectReport {
  int label = 0;  // number in the label image (1.., raster order of first pixel)
  hls::labelling::Object object;
  hls::warning::ObjectEval eval;  // the warning stage's arithmetic for it
  std::array<double, 7> hu{};
  int target = -1;  // index into FrameOutput::targets (-1: not measurable)
  std::string cls = "other";  // its target's class: pedestrian, bike, other
  int track = -1;             // its target's tracker id (pedestrians and bikes)
};

/// Parts at nearly one depth that touch in the image, taken as one physical object
/// (host/app/group.hpp), classified and tracked.
struct TargetReport {
  std::vector<int> labels;
  hls::labelling::Object object;  // the parts' union
  hls::warning::ObjectEval eval;  // the stage's arithmetic on the union
  std::array<double, 3> hu{};
  std::string cls = "other";
  int track = -1;
  bool has_speed = false;
  std::array<double, 3> velocity_mps{};  // vehicle axes: x right, y up, z ahead
};

/// One frame through the chain.
struct FrameOutput {
  cv::Mat left, right;  // rectified grey
  cv::Mat disparity;    // CV_16S, Q11.4 (after the road stage, and ground removal when on)
  cv::Mat road_mask;    // CV_8U, 255 where the road stage removed a valid disparity
  labelling::Segmentation segmentation;
  hls::warning::FrameResult result;  // the warning stage's word
  bool input_error = false;          // the pipeline's input checks flagged this pair
  int deciding_label = 0;            // 0: none
  std::vector<ObjectReport> objects;  // by label
  std::vector<TargetReport> targets;
  cv::Mat overlay;                    // BGR, Fig. 5.11 b
};

/// What another engine's stages (the Verilated pipeline, sim/pipeline/pipeline_chain.hpp) made of one
/// pair: the rectified pair, the disparity map, the object table and the frame result.
struct StageOutputs {
  cv::Mat left, right;  // rectified grey
  cv::Mat disparity;    // CV_16S, Q11.4, what the labelling stage took
  cv::Mat road_mask;    // CV_8U, 255 where the road stage removed a valid disparity
  hls::road::Line road;  // the road the frame was gated with (heights are above it)
  std::vector<hls::labelling::Object> objects;  // as the stage emitted them
  hls::labelling::FrameStatus status;
  hls::warning::FrameResult result;
  bool input_error = false;  // either camera's frame broke the stream geometry
};
/// Runs rectify, disparity, labelling and warning on one raw (or rectified) pair.
using StageEngine = std::function<StageOutputs(const cv::Mat& left, const cv::Mat& right)>;

/// The chain, keeping the tracker's state from frame to frame.
class Runner {
 public:
  /// `maps` empty: the pairs are already rectified. `engine` empty: the stages' C++ models run
  /// here; otherwise `engine` runs them and the C++ models check its every object and frame
  /// result (std::logic_error on a difference). Throws std::invalid_argument naming the
  /// setting that a stage cannot take.
  Runner(const RunOptions& options, std::optional<RectifyMaps> maps, StageEngine engine = {});
  ~Runner();
  FrameOutput process(const cv::Mat& left_grey, const cv::Mat& right_grey);
  const RunOptions& options() const { return opt_; }

 private:
  struct AppLayer;
  void classify_and_track(FrameOutput& out, const hls::warning::WarningConfig& wcfg,
                          const hls::road::Line& road);
  RunOptions opt_;
  std::optional<RectifyMaps> maps_;
  // The C++ engine's rectifiers of raw pairs, one stage per camera for the whole sequence.
  std::unique_ptr<rectify::Rectifier> rect_left_, rect_right_;
  StageEngine engine_;
  std::unique_ptr<AppLayer> app_;
  std::unique_ptr<road::RoadFilter> road_;  // the road stage's state from frame to frame
};

/// The frame's line of results.jsonl: frame, severity, distance_m, closest_uv, disparity, bbox,
/// objects, flags, and the deciding object's label, class and track.
nlohmann::json frame_json(int frame, const FrameOutput& out);
/// The warning stage's word alone: severity, distance_m, closest_uv, disparity, bbox,
/// in_tunnel, objects, obstacles, flags.
nlohmann::json result_json(const hls::warning::FrameResult& r);

/// "none", "low", "medium", "high".
using hls::warning::severity_name;

}  // namespace scw::app
