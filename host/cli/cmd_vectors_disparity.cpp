// SPDX-License-Identifier: Apache-2.0
// `scw vectors disparity`: writes a golden vector set of the disparity stage
// (host/vectors/disparity_set.hpp).
#include <iostream>
#include <memory>
#include <string>

#include "host/cli/commands.hpp"
#include "host/vectors/disparity_set.hpp"

namespace scw::cli {

namespace vec = scw::vectors;

void add_vectors_disparity_command(CLI::App& vectors) {
  struct Options {
    std::string preset, out;
    std::string data_dir = "data/tsukuba";
  };
  auto o = std::make_shared<Options>();
  auto* cmd = vectors.add_subcommand(
      "disparity", "Write a disparity golden vector set (left + right in, disparities out)");
  cmd->add_option("--preset", o->preset,
                  "texture (64x24 random texture with known shifts, N = 5, d 0..15, thesis "
                  "mode) or tsukuba (96x48 crop of the bundled pair, N = 9, d 0..15, opencv mode)")
      ->required()
      ->check(CLI::IsMember(vec::disparity_presets()));
  cmd->add_option("--out", o->out, "Vector set directory to write")->required();
  cmd->add_option("--data-dir", o->data_dir, "Folder with the Tsukuba PPMs");
  cmd->callback([o] {
    const auto s = vec::write_disparity_set(vec::disparity_preset(o->preset, o->data_dir), o->out);
    std::cout << "C++ model: " << s.beats << " beats equal the direct reference (" << s.cycles
              << " cycles)\n";
    if (s.known_shifts)
      std::cout << "known shifts: " << s.shifts_right << " of " << s.shifts_valid
                << " computed pixels find their true disparity\n";
    std::cout << "wrote " << o->out << "/ (" << s.width << "x" << s.height << ", P = " << s.ppc
              << ", N = " << s.window << ", d " << s.dmin << ".." << s.dmax << ", " << s.mode
              << " mode)\n";
  });
}

}  // namespace scw::cli
