// SPDX-License-Identifier: Apache-2.0
// `scw vectors warning`: writes a golden vector set of the warning stage
// (host/vectors/warning_set.hpp).
#include <iostream>
#include <memory>
#include <string>

#include "host/cli/commands.hpp"
#include "host/vectors/warning_set.hpp"

namespace scw::cli {

namespace vec = scw::vectors;

void add_vectors_warning_command(CLI::App& vectors) {
  struct Options {
    std::string preset, out;
  };
  auto o = std::make_shared<Options>();
  auto* cmd = vectors.add_subcommand(
      "warning", "Write a warning golden vector set (object tables in, frame results out)");
  cmd->add_option("--preset", o->preset,
                  "thesis (hand-placed objects, one per rule of eq. 5.2, incl. the worked "
                  "example), random (64 seeded random tables) or malformed (broken tables, each "
                  "followed by a good one)")
      ->required()
      ->check(CLI::IsMember(vec::warning_presets()));
  cmd->add_option("--out", o->out, "Vector set directory to write")->required();
  cmd->callback([o] {
    const auto s = vec::write_warning_set(vec::warning_preset(o->preset), o->out);
    std::cout << "C++ model: " << s.frames << " frames, " << s.words_in << " words in, "
              << s.results << " results, checked against a plain fold of evaluate() (" << s.cycles
              << " cycles)\n";
    std::cout << "wrote " << o->out << "/ (" << s.frames << " frames, " << s.words_in
              << " words in, " << s.objects << " objects, " << s.results << " results)\n";
  });
}

}  // namespace scw::cli
