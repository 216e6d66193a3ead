// SPDX-License-Identifier: Apache-2.0
// `scw vectors labelling`: writes a golden vector set of the labelling stage
// (host/vectors/labelling_set.hpp).
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "host/cli/commands.hpp"
#include "host/cli/set_options.hpp"
#include "host/vectors/labelling_set.hpp"
#include "host/vectors/vector_set.hpp"

namespace scw::cli {

namespace vec = scw::vectors;

void add_vectors_labelling_command(CLI::App& vectors) {
  struct Options {
    int frames = 0;  // 0: as given
    std::string preset;
    SetOut set;
    std::string data_dir = "data/tsukuba";
    vec::UserMap map;
    std::vector<int> roi, tiles;
  };
  auto o = std::make_shared<Options>();
  auto* cmd = vectors.add_subcommand(
      "labelling", "Write a labelling golden vector set (disparities in, object words out)");
  auto* preset = cmd->add_option(
      "--preset", o->preset,
      "shapes (five 64x48 adversarial shapes, 3x4 tiles), tsukuba (64x48 crop of the bundled "
      "ground truth, 2x2 tiles, min area 4) or overflow (a tile and an object overflow, then a "
      "normal frame)");
  preset->check(CLI::IsMember(vec::labelling_presets()));
  cmd->add_option("--disparity", o->map.disparity,
                  "Your disparity maps instead of a preset, one a frame, sent back to back: the "
                  "16-bit Q11.4 PNGs `scw disparity --out16` writes")
      ->check(CLI::ExistingFile)
      ->excludes(preset);
  cmd->add_option("--roi", o->roi,
                  "With --disparity: X Y W H of the crop, the same in every frame (the vectors "
                  "build: up to 64 x 48)")
      ->expected(4);
  cmd->add_option("--tiles", o->tiles, "With --disparity: tiles across and down")->expected(2);
  cmd->add_option("--config", o->map.build,
                  "With --disparity: the build: vectors (up to 64 x 48, 4 x 4 tiles, 64 objects; "
                  "the committed sets) or the pipeline's small, tsukuba or thesis (1280 x 480, "
                  "8 x 4 tiles, 256 objects)")
      ->check(CLI::IsMember(vec::labelling_builds()));
  cmd->add_option("--floor", o->map.floor, "With --disparity: the lowest valid value (Q11.4)");
  cmd->add_option("--min-area", o->map.min_area, "With --disparity: the smallest object");
  add_set_frames_option(cmd, o->frames);
  add_set_out_options(cmd, o->set);
  cmd->add_option("--data-dir", o->data_dir, "Folder with truedisp.row3.col3.pgm");
  cmd->callback([o, cmd] {
    if (o->preset.empty() && o->map.disparity.empty())
      throw CLI::ValidationError("give --preset NAME, or your maps with --disparity FILE ...");
    vec::LabellingPreset p;
    if (!o->preset.empty()) {
      p = vec::labelling_preset(o->preset, o->data_dir);
    } else {
      if (!o->roi.empty()) o->map.roi = cv::Rect(o->roi[0], o->roi[1], o->roi[2], o->roi[3]);
      if (!o->tiles.empty()) {
        o->map.tiles_x = o->tiles[0];
        o->map.tiles_y = o->tiles[1];
      }
      p = vec::labelling_frames(o->map);
    }
    if (o->frames > 0) vec::repeat_frames(p.frames, o->frames);
    write_set_parts(*cmd, o->set, p.frames.size(), [&](const auto& r, const auto& dir) {
      auto part = p;
      part.frames = vec::frames_in(p.frames, r);
      const auto s = vec::write_labelling_set(part, dir);
      std::cout << "C++ model: " << s.frames << " frames, " << s.words
                << " words, checked against the flood-fill reference (" << s.cycles << " cycles)\n";
      std::cout << "wrote " << dir.string() << "/ (" << s.frames << " frames of " << s.width << "x"
                << s.height << ", " << s.tiles_x << "x" << s.tiles_y << " tiles, " << s.objects
                << " objects, " << s.words << " words)\n";
    });
  });
}

}  // namespace scw::cli
