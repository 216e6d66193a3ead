// SPDX-License-Identifier: Apache-2.0
// Writing a rendered scene: the raw pairs, the calibration, per-frame truth (truth.jsonl) and
// scene.json with the `scw run` line that suits it (docs/scene.md).
#pragma once

#include <functional>
#include <string>

#include <nlohmann/json.hpp>

#include "host/scene/render.hpp"
#include "host/scene/rig.hpp"
#include "host/scene/scene.hpp"
#include "host/scene/truth.hpp"

namespace scw::host::scene {

/// "0007_left.png" / "0007_right.png": the names `scw run --sequence` pairs.
std::string left_name(int frame);
std::string right_name(int frame);

/// M1 D1 M2 D2 R T (CV_64F, D as 1 x 5, T 3 x 1) and image_width, image_height as
/// cv::FileStorage YAML: what rectify::load_stereo_calibration reads. Throws std::runtime_error
/// when the file cannot be written.
void write_calibration(const std::string& path, const StereoRig& rig);

/// One line of truth.jsonl (docs/scene.md lists the fields).
nlohmann::json truth_json(const FrameTruth& t);

/// Every number of the rig, the sampling and the noise.
nlohmann::json rig_json(const StereoRig& rig, int subsamples, const RenderOptions& options);

/// The `scw run` settings the scenes are made for: the thesis-size hardware build (window 21,
/// 45 candidates 12 .. 56), 8 x 4 tiles; no ground removal: the rendered road's faint grain
/// leaves it nothing to remove (docs/scene.md), and the chain is then the thesis's four stages.
struct RunSettings {
  int min_disp = 12, max_disp = 56, window = 21;
  int tiles_x = 8, tiles_y = 4;
  bool ground = false;
  double camera_height_m = default_camera_in_vehicle()[1];
  double camera_pitch_deg = 0.0;  // the rig's mounting pitch (the road stage's first horizon)
};

/// The full `scw run` command line for the scene in `dir`, results to `out_dir`.
std::string run_command(const std::string& dir, const std::string& out_dir,
                        const RunSettings& run, double frame_period_s);
/// `scw eval --truth DIR --results OUT/results.jsonl`.
std::string eval_command(const std::string& dir, const std::string& out_dir);

/// scene.json: preset, frames, frame_period_s, image_size, rig, run, command, eval_command.
nlohmann::json scene_json(const Sequence& s, const StereoRig& rig, int subsamples,
                          const RenderOptions& options, const RunSettings& run,
                          const std::string& dir, const std::string& out_dir);

/// What write_scene made.
struct WrittenScene {
  int frames = 0;
  std::string dir, run_out_dir;  // run_out_dir: where the suggested `scw run` writes
  std::string run_command, eval_command;
};

/// Makes `dir` (with parents) and checks it can take a scene of `frames` frames. Throws
/// std::runtime_error when it cannot be made or written, or holds NNNN_left/right.png frames
/// numbered `frames` or more (left from a longer scene: `scw run --sequence` would pair them too).
void prepare_output_dir(const std::string& dir, int frames);

/// Renders every frame and writes DIR/NNNN_left.png, NNNN_right.png, calibration.yml,
/// truth.jsonl and scene.json (prepare_output_dir first); `progress(done, total)` after each
/// frame. Throws std::runtime_error naming any file it cannot write.
WrittenScene write_scene(const Sequence& s, const Renderer& renderer, const std::string& dir,
                         const RenderOptions& options,
                         const std::function<void(int, int)>& progress = {});

}  // namespace scw::host::scene
