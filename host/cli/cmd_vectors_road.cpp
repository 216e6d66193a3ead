// SPDX-License-Identifier: Apache-2.0
// `scw vectors road`: writes a golden vector set of the road stage (host/vectors/road_set.hpp).
#include <iostream>
#include <memory>
#include <string>

#include "host/cli/commands.hpp"
#include "host/vectors/road_set.hpp"

namespace scw::cli {

namespace vec = scw::vectors;

void add_vectors_road_command(CLI::App& vectors) {
  struct Options {
    std::string preset, out;
  };
  auto o = std::make_shared<Options>();
  auto* cmd = vectors.add_subcommand(
      "road",
      "Write a road-stage golden vector set (disparities in, disparities without the "
      "road out)");
  cmd->add_option("--preset", o->preset,
                  "street (six 64x48 maps, the road fitted and moving at every frame) or "
                  "implausible (six maps whose fits the plausibility rules refuse: the road "
                  "stays the nominal one)")
      ->required()
      ->check(CLI::IsMember(vec::road_presets()));
  cmd->add_option("--out", o->out, "Vector set directory to write")->required();
  cmd->callback([o] {
    const auto s = vec::write_road_set(vec::road_preset(o->preset), o->out);
    std::cout << "C++ model: " << s.frames << " frames, " << s.beats << " beats, " << s.cycles
              << " cycles; " << s.fits << " fits changed the road; " << s.removed
              << " pixels removed, equal to the floating-point reference's";
    if (s.band_edge > 0) std::cout << " but " << s.band_edge << " at a band's edge";
    std::cout << "; roads within " << s.road_error_px << " px of the reference's\n";
    for (std::size_t f = 0; f < s.roads.size(); ++f)
      std::cout << "  frame " << f << ": road a " << s.roads[f].a << " b " << s.roads[f].b
                << ", its pixels' fit: " << vec::road_fit_name(s.verdicts[f]) << "\n";
    std::cout << "wrote " << o->out << "/ (" << s.frames << " frames of " << s.width << "x"
              << s.height << ", P = " << vec::RoadVecParams::kPpc << ")\n";
  });
}

}  // namespace scw::cli
