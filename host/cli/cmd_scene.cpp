// SPDX-License-Identifier: Apache-2.0
// `scw scene`: renders a preset street scene through the synthetic stereo rig and writes the raw
// pairs, the calibration and per-frame ground truth (docs/scene.md).
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>

#include "host/cli/commands.hpp"
#include "host/cli/progress.hpp"
#include "host/scene/presets.hpp"
#include "host/scene/render.hpp"
#include "host/scene/write.hpp"

namespace scw::cli {
namespace {

struct SceneOptions {
  std::string preset, out_dir;
  int frames = 0;
  bool frames_given = false;
  std::uint32_t seed = 1;
  bool markings = false;
  double grain = -1.0;  // < 0: the preset's
  // rays per pixel and axis
  int subsamples = host::scene::Renderer::kDefaultSubsamples;
};

void run_scene(const SceneOptions& o) {
  namespace sc = host::scene;
  // Everything that can be refused is refused before the ray tables take their seconds.
  const sc::Sequence seq = sc::make_preset(
      o.preset, o.frames_given ? std::optional<int>(o.frames) : std::nullopt, o.seed);
  const int n = static_cast<int>(seq.frames.size());
  sc::prepare_output_dir(o.out_dir, n);
  std::cerr << "scene: " << seq.preset << ", " << n << " frames " << seq.frame_period_s
            << " s apart, seed " << seq.seed << "; building the ray tables\n";
  sc::StereoRig rig;
  rig.pitch_rad = seq.pitch_rad;
  const sc::Renderer renderer(rig, o.subsamples);
  sc::RenderOptions render{1.0, o.seed, seq.ground};
  render.ground.markings = render.ground.markings || o.markings;
  if (o.grain >= 0.0) render.ground.grain_contrast = o.grain;
  Progress bar(static_cast<std::size_t>(n));
  const auto progress = [&bar](int done, int) { bar.show(static_cast<std::size_t>(done)); };
  const sc::WrittenScene w =
      sc::write_scene(seq, renderer, o.out_dir, render, progress);
  std::cout << "wrote " << w.frames << " raw pairs (" << sc::left_name(0) << " .. "
            << sc::right_name(w.frames - 1) << "), calibration.yml, truth.jsonl and scene.json in "
            << w.dir << "\n"
            << "run the chain on them:\n  " << w.run_command << "\n"
            << "then score the results against the truth:\n  " << w.eval_command << "\n";
}

std::string preset_help() {
  std::ostringstream os;
  os << "Scene: ";
  bool first = true;
  for (const auto& p : host::scene::preset_names()) {
    os << (first ? "" : ", ") << p << " (" << host::scene::default_frames(p) << " frames)";
    first = false;
  }
  return os.str();
}

}  // namespace

void add_scene_command(CLI::App& app) {
  auto o = std::make_shared<SceneOptions>();
  auto* cmd = app.add_subcommand(
      "scene",
      "Render a synthetic street scene (textured road and objects) through a calibrated, "
      "distorted stereo rig: raw pairs, calibration.yml and ground truth for scw run");
  cmd->add_option("--preset", o->preset, preset_help())->required();
  auto* frames = cmd->add_option("--frames", o->frames,
                                 "Number of frames, at least 2, spread evenly over the preset's "
                                 "motion (default: the preset's own)");
  cmd->add_option("--out-dir", o->out_dir,
                  "Folder for NNNN_left.png, NNNN_right.png, calibration.yml, truth.jsonl, "
                  "scene.json")
      ->required();
  cmd->add_option("--seed", o->seed, "Texture and camera-noise seed")->capture_default_str();
  cmd->add_flag("--markings", o->markings,
                "Paint dashed lane markings on the road (the street presets always do; far dashes "
                "merge into one marking that the warning stage takes for an obstacle beside the "
                "tunnel: docs/scene.md)");
  cmd->add_option("--grain", o->grain,
                  "Road grain contrast, grey levels (two standard deviations; default: the "
                  "preset's, 3 for the thesis presets, 25 or 60 for the street presets)")
      ->check(CLI::Range(0.0, 100.0));
  cmd->add_option("--subsamples", o->subsamples,
                  "Rays per pixel and axis: the default renders the scenes docs/scene.md "
                  "measured; 1 casts a ninth of the rays, a quick draft whose edges and grain "
                  "alias")
      ->capture_default_str()
      ->check(CLI::Range(1, 8));
  cmd->callback([o, frames] {
    o->frames_given = frames->count() > 0;
    run_scene(*o);
  });
}

}  // namespace scw::cli
