// SPDX-License-Identifier: Apache-2.0
// `scw vectors warning`: writes a golden vector set of the warning stage
// (host/vectors/warning_set.hpp).
#include <iostream>
#include <memory>
#include <string>

#include "host/cli/commands.hpp"
#include "host/cli/set_options.hpp"
#include "host/cli/value_checks.hpp"
#include "host/vectors/vector_set.hpp"
#include "host/vectors/warning_set.hpp"

namespace scw::cli {

namespace vec = scw::vectors;

void add_vectors_warning_command(CLI::App& vectors) {
  struct Options {
    int frames = 0;  // 0: as given
    std::string preset, rule = "spread";
    SetOut set;
    vec::UserTables user;
    std::vector<int> size;
  };
  auto o = std::make_shared<Options>();
  auto* cmd = vectors.add_subcommand(
      "warning", "Write a warning golden vector set (object tables in, frame results out)");
  auto* preset = cmd->add_option(
      "--preset", o->preset,
      "thesis (hand-placed objects, one per rule of eq. 5.2, incl. the worked example), random "
      "(64 seeded random tables) or malformed (broken tables, each followed by a good one)");
  preset->check(CLI::IsMember(vec::warning_presets()));
  auto* objects =
      cmd->add_option("--objects", o->user.objects,
                      "Your object tables (instead of a preset): CSV with a frame column and the "
                      "object word's fields by name, as a labelling set's expected_objects.csv")
          ->check(CLI::ExistingFile);
  objects->excludes(preset);
  cmd->add_option("--status", o->user.status,
                  "With --objects: each frame's flags (frame, tile_overflow, object_overflow, "
                  "stream_error), as a labelling set's expected_status.csv")
      ->check(CLI::ExistingFile)
      ->needs(objects);
  auto& w = o->user.setup;
  cmd->add_option("--image-size", o->size, "With --objects: W H of the image (default 1280 480)")
      ->expected(2)
      ->check(CLI::PositiveNumber);
  cmd->add_option("--focal", w.focal_px, "With --objects: focal length, px")
      ->capture_default_str()
      ->check(positive("px", "700"));
  cmd->add_option("--baseline", w.baseline_m, "With --objects: baseline, m")
      ->capture_default_str()
      ->check(positive("m", "0.54"));
  cmd->add_option("--cx", w.cu_px, "With --objects: principal point u, px (default: centre)")
      ->check(non_negative("px", "639.5"));
  cmd->add_option("--cy", w.cv_px, "With --objects: principal point v, px (default: centre)")
      ->check(non_negative("px", "239.5"));
  cmd->add_option("--max-disp", w.d_limit_px,
                  "With --objects: the top of the disparity search; objects reaching it are too "
                  "close")
      ->capture_default_str()
      ->check(positive("px", "64"));
  cmd->add_option("--distance-rule", o->rule, "With --objects: spread (default) or closest")
      ->check(CLI::IsMember({"spread", "closest"}));
  cmd->add_option("--spread-k", w.spread_k, "With --objects: k of the spread rule")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 15.9375));
  cmd->add_option("--config", o->user.build,
                  "With --objects: the build: vectors (a reciprocal table below 128 px; the "
                  "committed sets), or the pipeline's small, tsukuba (32 px) or thesis (128 px)")
      ->check(CLI::IsMember(vec::warning_builds()));
  add_set_frames_option(cmd, o->frames);
  add_set_out_options(cmd, o->set);
  cmd->callback([o, cmd] {
    if (o->preset.empty() && o->user.objects.empty())
      throw CLI::ValidationError("give --preset NAME, or your tables with --objects FILE.csv");
    if (!o->size.empty()) {
      o->user.width = o->size[0];
      o->user.height = o->size[1];
    }
    o->user.setup.distance_rule = o->rule == "closest" ? hls::warning::DistanceRule::kClosest
                                                       : hls::warning::DistanceRule::kSpread;
    auto p = o->preset.empty() ? vec::warning_user_preset(o->user) : vec::warning_preset(o->preset);
    if (o->frames > 0) vec::repeat_frames(p.frames, o->frames);
    write_set_parts(*cmd, o->set, p.frames.size(), [&](const auto& r, const auto& dir) {
      auto part = p;
      part.frames = vec::frames_in(p.frames, r);
      const auto s = vec::write_warning_set(part, dir);
      std::cout << "C++ model: " << s.frames << " frames, " << s.words_in << " words in, "
                << s.results << " results, checked against a plain fold of evaluate() (" << s.cycles
                << " cycles)\n";
      std::cout << "wrote " << dir.string() << "/ (" << s.frames << " frames, " << s.words_in
                << " words in, " << s.objects << " objects, " << s.results << " results)\n";
    });
  });
}

}  // namespace scw::cli
