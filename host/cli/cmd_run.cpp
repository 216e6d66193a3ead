// SPDX-License-Identifier: Apache-2.0
// `scw run`: the whole chain on a stereo pair or a folder of numbered pairs; writes the
// rectified pair, disparity, labels, the warning overlay and results.jsonl (docs/warning.md,
// "`scw run`").
#include <iostream>
#include <memory>
#include <string>
#include <tuple>

#include "host/app/camera.hpp"
#include "host/app/frame_files.hpp"
#include "host/app/run.hpp"
#include "host/app/sequence.hpp"
#include "host/cli/commands.hpp"
#include "host/cli/progress.hpp"
#include "host/cli/run_options.hpp"
#include "host/cli/shard_option.hpp"
#include "host/cli/value_checks.hpp"
#include "host/io/image_file.hpp"
#include "host/labelling/run_model.hpp"
#include "host/pipeline/rtl_engine.hpp"
#include "sim/core/simulator.hpp"

namespace scw::cli {
namespace {

struct RunOptions {
  std::string left, right, sequence, out_dir;
  app::CameraInput camera;
  std::string tiles, engine = "cpp", mode = disparity::mode_name(disparity::kDefaultMode);
  std::string pictures = "all", shard;
  app::RunOptions run;
  int segments = 0;
  int threads = 1;
};

void run_chain(RunOptions& o, const CLI::App& cmd) {
  sim::check_threads(o.threads, "--threads");  // the simulator's rule, as scw sim checks it
  if (o.threads != 1 && o.engine != "rtl")
    throw CLI::ValidationError("--threads",
                               "two threads step the Verilated chain: give "
                               "--engine rtl with it, or leave --threads at 1");
  if (!o.tiles.empty()) std::tie(o.run.tiles_x, o.run.tiles_y) = labelling::parse_tiles(o.tiles);
  o.run.mode = disparity::mode_from_name(o.mode);
  const auto pairs = app::pairs_of(o.left, o.right, o.sequence);
  const cv::Mat first = host::io::read_grey_image(pairs.front().first.string());
  auto camera = app::set_up_camera(o.camera, first.size(), o.run.warning);
  std::cerr << "run: " << app::run_summary(o.run, pairs.size(), first.size()) << "\n";
  if (o.engine == "rtl")
    std::cerr << "run: the stages run as Verilated RTL; the C++ models check every object and "
                 "frame result\n";
  const auto make_runner = [&] {  // at the first frame and where the state restarts
    app::StageEngine engine;
    if (o.engine == "rtl")
      engine =
          host::pipeline::make_rtl_engine(o.run, first.cols, first.rows, camera.knots, o.threads);
    return std::make_unique<app::Runner>(o.run, camera.maps, std::move(engine));
  };
  const app::SequenceSplit split{shard_of(o.shard), o.segments};
  const std::size_t frames = app::plan_split(split, pairs.size()).range.size();
  const auto pictures = app::pictures_from_name(o.pictures);
  Progress progress(frames);
  remove_old_manifest(o.out_dir);
  app::run_pairs(
      make_runner, pairs, first.size(), o.out_dir,
      [&](std::size_t i, const app::FrameOutput& f, const nlohmann::json& j) {
        if (pairs.size() > 1)
          progress.show(i + 1, app::frame_note(f));
        else
          std::cout << j.dump() << "\n";
      },
      pictures, split);
  app::ShardManifest m;
  m.total = pairs.size();
  m.concatenate = {"results.jsonl"};
  write_manifest_if_sharded(o.shard, cmd, {"out-dir"}, m, o.out_dir);
  std::cout << "wrote " << frames << (frames == 1 ? " frame" : " frames") << " in " << o.out_dir
            << " (results.jsonl; a frame's " << app::frame_file_names(pictures) << ")\n";
}

}  // namespace

void add_run_command(CLI::App& app) {
  auto o = std::make_shared<RunOptions>();
  auto* cmd = app.add_subcommand(
      "run", "The whole chain (rectify, disparity, labelling, warning) on the stages' C++ models, "
             "then classification, tracking and the warning overlay");
  add_camera_options(cmd, o->camera);
  cmd->add_option("--left", o->left, "Left image")->check(CLI::ExistingFile);
  cmd->add_option("--right", o->right, "Right image")->check(CLI::ExistingFile);
  cmd->add_option("--sequence", o->sequence, "Folder of numbered pairs (NNNN_left.png, NNNN_right.png)");
  cmd->add_option("--out-dir", o->out_dir, "Where the pictures and results.jsonl go")->required();
  cmd->add_option("--pictures", o->pictures,
                  "Pictures a frame writes: all (the rectified pair, disparity, labels, overlay, "
                  "road), overlay, or none (objects.csv and results.jsonl are always written)")
      ->capture_default_str()
      ->check(CLI::IsMember({"none", "overlay", "all"}));
  cmd->add_option("--threads", o->threads,
                  "with --engine rtl: 1, or 2 to step the disparity and road stages on a second "
                  "thread, the same results (docs/sim.md)")
      ->capture_default_str();
  cmd->add_option("--engine", o->engine,
                  "cpp: the stages' C++ models; rtl: every block Verilated (rectified pairs, a "
                  "built size: small up to 128 x 96, window 9, 16 disparities, 2x2 tiles)")
      ->capture_default_str()
      ->check(CLI::IsMember({"cpp", "rtl"}));
  cmd->add_option("--tiles", o->tiles, "Labelling tile grid, columns x rows (default 4x4)");
  cmd->add_option("--window", o->run.window, "SAD window N")->capture_default_str()->check(odd_window());
  cmd->add_option("--min-disp", o->run.min_disp, "Smallest candidate disparity")->capture_default_str()
      ->check(non_negative("px", "0"));
  cmd->add_option("--max-disp", o->run.max_disp,
                  "Largest candidate; objects reaching it are flagged too_close")
      ->capture_default_str()->check(positive("px", "64"));
  cmd->add_option("--mode", o->mode, "Disparity mode (scw disparity --help)")->capture_default_str()
      ->check(CLI::IsMember({"thesis", "opencv"}));
  cmd->add_option("--edge-candidates", o->run.edge_candidates, disparity::kEdgeCandidatesHelp)
      ->capture_default_str()
      ->check(non_negative("", "32"));
  cmd->add_option("--min-area", o->run.min_area, "Smallest object, px")->capture_default_str()
      ->check(non_negative("px", "50"));
  cmd->add_flag("!--no-road", o->run.road,
                "Keep the road in the labelling's input (the road stage passes every pixel)");
  cmd->add_flag("--ground", o->run.ground, "Ground-plane removal (thesis 6.2) before labelling");
  cmd->add_option("--camera-height", o->run.camera_height_m,
                  "Camera height above the road, m (the road stage's first road, ground removal's slope)")->capture_default_str()
      ->check(positive("m", "1.2"));
  cmd->add_option("--camera-pitch", o->run.camera_pitch_deg,
                  "Camera's downward pitch, degrees (the road stage's first horizon; the road "
                  "it fits replaces it)")->capture_default_str();
  add_warning_options(cmd, o->run.warning);
  cmd->add_option("--classifier", o->run.classifier, "Model from scw train (SVM or neural network); "
                  "default: the parallelepiped classifier of Table 5.4")->check(CLI::ExistingFile);
  cmd->add_option("--classifier-s", o->run.classifier_s,
                  "The parallelepiped classifier's interval m +- s sigma (Table 5.5)")
      ->capture_default_str()->check(positive("sigma", "2"));
  cmd->add_flag("--kalman", o->run.kalman, "Track with a cv::KalmanFilter (constant velocity)");
  cmd->add_option("--frame-period", o->run.frame_period_s, "Seconds between frames (speed)")
      ->capture_default_str()->check(positive("s", "0.01"));
  add_shard_option(cmd, o->shard, "sequence's frames");
  add_segments_option(cmd, o->segments, "the tracker and the road stage");
  cmd->add_flag("--overlay-on-labels", o->run.overlay_on_labels,
                "Draw the overlay on the label picture instead of the left image");
  cmd->callback([o, cmd] { run_chain(*o, *cmd); });
}

}  // namespace scw::cli
