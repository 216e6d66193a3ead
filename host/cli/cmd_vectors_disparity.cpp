// SPDX-License-Identifier: Apache-2.0
// `scw vectors disparity`: writes a golden vector set of the disparity stage
// (host/vectors/disparity_set.hpp).
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "host/cli/commands.hpp"
#include "host/cli/set_options.hpp"
#include "host/vectors/disparity_set.hpp"
#include "host/vectors/vector_set.hpp"

namespace scw::cli {

namespace vec = scw::vectors;

void add_vectors_disparity_command(CLI::App& vectors) {
  struct Options {
    int frames = 0;  // 0: as given
    std::string preset, mode = "opencv";
    SetOut set;
    std::string data_dir = "data/tsukuba";
    vec::UserPair pair;
    std::vector<int> roi;
  };
  auto o = std::make_shared<Options>();
  auto* cmd = vectors.add_subcommand(
      "disparity", "Write a disparity golden vector set (left + right in, disparities out)");
  auto* preset = cmd->add_option(
      "--preset", o->preset,
      "texture (64x24 random texture with known shifts, N = 5, d 0..15, thesis mode), tsukuba "
      "(96x48 crop of the bundled pair, N = 9, d 0..15, opencv mode) or tsukuba_edge (the same "
      "with the left edge band)");
  preset->check(CLI::IsMember(vec::disparity_presets()));
  auto* left =
      cmd->add_option("--left", o->pair.left,
                      "Your rectified left images (instead of a preset), a frame each, sent back "
                      "to back")
          ->check(CLI::ExistingFile);
  auto* right = cmd->add_option("--right", o->pair.right, "Your rectified right images, as many")
                    ->check(CLI::ExistingFile);
  left->needs(right)->excludes(preset);
  right->needs(left);
  cmd->add_option("--roi", o->roi,
                  "With --left/--right: X Y W H of the crop to match, the same in every frame "
                  "(the vectors build takes up to 128 x 64)")
      ->expected(4);
  cmd->add_option("--window", o->pair.window,
                  "With --left/--right: N (the vectors build: 5 or 9; small and tsukuba: 9; "
                  "thesis: 21)")
      ->check(CLI::IsMember({5, 9, 21}));
  cmd->add_option("--config", o->pair.build,
                  "With --left/--right: the build: vectors (P = 2, up to 128 x 64, 16 "
                  "candidates; the committed sets), or the pipeline's small (128 x 96), tsukuba "
                  "(384 x 288) or thesis (1280 x 480, N 21, 45 candidates) at --ppc")
      ->check(CLI::IsMember(vec::disparity_builds()));
  cmd->add_option("--ppc", o->pair.ppc, "With --config small, tsukuba or thesis: pixels a beat")
      ->check(CLI::IsMember({1, 2, 4}));
  cmd->add_option("--mode", o->mode, "With --left/--right: thesis or opencv")
      ->check(CLI::IsMember({"thesis", "opencv"}));
  cmd->add_option("--dmin", o->pair.dmin, "With --left/--right: the first of the 16 candidates");
  cmd->add_option("--edge-candidates", o->pair.edge_candidates,
                  "With --left/--right: decide the left edge band from K candidates (0: blind)");
  add_set_frames_option(cmd, o->frames);
  add_set_out_options(cmd, o->set);
  cmd->add_option("--data-dir", o->data_dir, "Folder with the Tsukuba PPMs");
  cmd->callback([o, cmd] {
    if (o->preset.empty() && o->pair.left.empty())
      throw CLI::ValidationError("give --preset NAME, or your pair with --left L --right R");
    vec::DisparityFrame f;
    if (!o->preset.empty()) {
      f = vec::disparity_preset(o->preset, o->data_dir);
    } else {
      o->pair.mode = disparity::mode_from_name(o->mode);
      if (!o->roi.empty()) o->pair.roi = cv::Rect(o->roi[0], o->roi[1], o->roi[2], o->roi[3]);
      f = vec::disparity_frames(o->pair);
    }
    if (o->frames > 0) {
      vec::repeat_frames(f.left, o->frames);
      vec::repeat_frames(f.right, o->frames);
    }
    write_set_parts(*cmd, o->set, f.left.size(), [&](const auto& r, const auto& dir) {
      auto part = f;
      part.left = vec::frames_in(f.left, r);
      part.right = vec::frames_in(f.right, r);
      const auto s = vec::write_disparity_set(part, dir);
      std::cout << "C++ model: " << s.beats << " beats equal the direct reference (" << s.cycles
                << " cycles)\n";
      if (s.known_shifts)
        std::cout << "known shifts: " << s.shifts_right << " of " << s.shifts_valid
                  << " computed pixels find their true disparity\n";
      std::cout << "wrote " << dir.string() << "/ (" << s.frames << " frame(s) of " << s.width
                << "x" << s.height << ", " << s.build << " build, P = " << s.ppc
                << ", N = " << s.window << ", d " << s.dmin << ".." << s.dmax << ", " << s.mode
                << " mode)\n";
    });
  });
}

}  // namespace scw::cli
