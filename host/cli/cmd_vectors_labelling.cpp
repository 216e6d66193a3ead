// SPDX-License-Identifier: Apache-2.0
// `scw vectors labelling`: writes a golden vector set of the labelling stage
// (host/vectors/labelling_set.hpp).
#include <iostream>
#include <memory>
#include <string>

#include "host/cli/commands.hpp"
#include "host/vectors/labelling_set.hpp"

namespace scw::cli {

namespace vec = scw::vectors;

void add_vectors_labelling_command(CLI::App& vectors) {
  struct Options {
    std::string preset, out;
    std::string data_dir = "data/tsukuba";
  };
  auto o = std::make_shared<Options>();
  auto* cmd = vectors.add_subcommand(
      "labelling", "Write a labelling golden vector set (disparities in, object words out)");
  cmd->add_option("--preset", o->preset,
                  "shapes (five 64x48 adversarial shapes, 3x4 tiles), tsukuba (64x48 crop of "
                  "the bundled ground truth, 2x2 tiles, min area 4) or overflow (a tile and an "
                  "object overflow, then a normal frame)")
      ->required()
      ->check(CLI::IsMember(vec::labelling_presets()));
  cmd->add_option("--out", o->out, "Vector set directory to write")->required();
  cmd->add_option("--data-dir", o->data_dir, "Folder with truedisp.row3.col3.pgm");
  cmd->callback([o] {
    const auto s = vec::write_labelling_set(vec::labelling_preset(o->preset, o->data_dir), o->out);
    std::cout << "C++ model: " << s.frames << " frames, " << s.words
              << " words, checked against the flood-fill reference (" << s.cycles << " cycles)\n";
    std::cout << "wrote " << o->out << "/ (" << s.frames << " frames of " << s.width << "x"
              << s.height << ", " << s.tiles_x << "x" << s.tiles_y << " tiles, " << s.objects
              << " objects, " << s.words << " words)\n";
  });
}

}  // namespace scw::cli
