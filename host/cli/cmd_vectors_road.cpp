// SPDX-License-Identifier: Apache-2.0
// `scw vectors road`: writes a golden vector set of the road stage (host/vectors/road_set.hpp).
#include <iostream>
#include <memory>
#include <string>

#include "host/cli/commands.hpp"
#include "host/cli/set_options.hpp"
#include "host/cli/value_checks.hpp"
#include "host/vectors/road_set.hpp"
#include "host/vectors/vector_set.hpp"

namespace scw::cli {

namespace vec = scw::vectors;

void add_vectors_road_command(CLI::App& vectors) {
  struct Options {
    int frames = 0;  // 0: as given
    std::string preset;
    SetOut set;
    vec::UserRoadMaps maps;
    std::vector<int> roi;
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
      ->check(CLI::IsMember(vec::road_presets()));
  cmd->add_option("--disparity", o->maps.disparity,
                  "Your disparity maps instead of a preset, one a frame (at least 4), sent back "
                  "to back: the 16-bit Q11.4 PNGs `scw disparity --out16` writes")
      ->check(CLI::ExistingFile)
      ->excludes("--preset");
  cmd->add_option("--roi", o->roi,
                  "With --disparity: X Y W H of the crop, the same in every frame (the vectors "
                  "build: up to 64 x 48)")
      ->expected(4);
  auto& m = o->maps;
  cmd->add_option("--focal", m.focal_px, "With --disparity: focal length, px")
      ->capture_default_str()
      ->check(positive("px", "700"));
  cmd->add_option("--baseline", m.baseline_m, "With --disparity: baseline, m")
      ->capture_default_str()
      ->check(positive("m", "0.54"));
  cmd->add_option("--cy", m.cy_px,
                  "With --disparity: the principal point's row in the whole map (default: its "
                  "centre)")
      ->check(non_negative("px", "239.5"));
  cmd->add_option("--camera-height", m.camera_height_m,
                  "With --disparity: the camera's height above the road, m (the nominal road)")
      ->capture_default_str()
      ->check(positive("m", "1.2"));
  cmd->add_option("--camera-pitch", m.camera_pitch_deg,
                  "With --disparity: the camera's downward pitch, degrees (the nominal horizon)")
      ->capture_default_str();
  cmd->add_option("--min-count", m.min_count,
                  "With --disparity: pixels a fit needs (default: 2000 scaled from 1280 x 480 to "
                  "the crop, at least 50)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--config", m.build,
                  "With --disparity: the build: vectors (P = 2, up to 64 x 48; the committed "
                  "sets) or the pipeline's small, tsukuba or thesis (1280 x 480) at --ppc")
      ->check(CLI::IsMember(vec::road_builds()));
  cmd->add_option("--ppc", m.ppc, "With --config small, tsukuba or thesis: pixels a beat")
      ->check(CLI::IsMember({1, 2, 4}));
  add_set_frames_option(cmd, o->frames);
  add_set_out_options(cmd, o->set);
  cmd->callback([o, cmd] {
    if (o->preset.empty() && o->maps.disparity.empty())
      throw CLI::ValidationError("give --preset NAME, or your maps with --disparity FILE ...");
    if (!o->roi.empty()) o->maps.roi = cv::Rect(o->roi[0], o->roi[1], o->roi[2], o->roi[3]);
    auto seq = o->preset.empty() ? vec::road_frames(o->maps) : vec::road_preset(o->preset);
    if (o->frames > 0) vec::repeat_frames(seq.frames, o->frames);
    write_set_parts(*cmd, o->set, seq.frames.size(), [&](const auto& r, const auto& dir) {
      auto part = seq;
      part.frames = vec::frames_in(seq.frames, r);
      const auto s = vec::write_road_set(part, dir);
      std::cout << "C++ model: " << s.frames << " frames, " << s.beats << " beats, " << s.cycles
                << " cycles; " << s.fits << " fits changed the road; " << s.removed
                << " pixels removed, equal to the floating-point reference's";
      if (s.band_edge > 0) std::cout << " but " << s.band_edge << " at a band's edge";
      std::cout << "; roads within " << s.road_error_px << " px of the reference's\n";
      for (std::size_t f = 0; f < s.roads.size(); ++f)
        std::cout << "  frame " << f << ": road a " << s.roads[f].a << " b " << s.roads[f].b
                  << ", its pixels' fit: " << vec::road_fit_name(s.verdicts[f]) << "\n";
      std::cout << "wrote " << dir.string() << "/ (" << s.frames << " frames of " << s.width << "x"
                << s.height << ", P = " << s.ppc << ")\n";
    });
  });
}

}  // namespace scw::cli
