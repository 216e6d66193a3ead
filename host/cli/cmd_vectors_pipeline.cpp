// SPDX-License-Identifier: Apache-2.0
// `scw vectors pipeline`: writes a golden vector set of the whole scw_pipeline top
// (host/vectors/pipeline_set.hpp).
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "host/app/pair_files.hpp"
#include "host/cli/commands.hpp"
#include "host/cli/set_options.hpp"
#include "host/io/image_file.hpp"
#include "host/vectors/pipeline_set.hpp"
#include "host/vectors/vector_set.hpp"

namespace scw::cli {

namespace vec = scw::vectors;

void add_vectors_pipeline_command(CLI::App& vectors) {
  struct Options {
    vec::PipelineSetOptions set;
    std::vector<std::string> left, right;
    std::string sequence, engine = "rtl";
    SetOut out;
  };
  auto o = std::make_shared<Options>();
  auto* cmd = vectors.add_subcommand(
      "pipeline",
      "Write a golden vector set of the scw_pipeline top: raw pairs and knots in, every stream "
      "between the stages and the frame results out");
  cmd->add_option("--config", o->set.config,
                  "Build of the top: small (its Verilated top checks the set) or thesis (1280 x "
                  "480; --engine cpp)")
      ->check(CLI::IsMember(vec::pipeline_set_configs()));
  cmd->add_option("--ppc", o->set.ppc, "Pixels per beat")->check(CLI::IsMember({1, 2}));
  auto* frames = cmd->add_option("--frames", o->set.frames,
                                 "Frames back to back: synthetic street frames, or the first K "
                                 "of your pairs")
                     ->check(CLI::Range(1, 100000));
  cmd->add_option("--size", o->set.width, "Synthetic frames: width (height is half of it)")
      ->check(CLI::IsMember({32, 64}));
  cmd->add_option("--seed", o->set.seed, "Synthetic frames: boxes' textures");
  auto* left = cmd->add_option("--left", o->left,
                               "Your left images (8-bit grey, one size), in order; rectified "
                               "unless --calib")
                   ->check(CLI::ExistingFile);
  auto* right = cmd->add_option("--right", o->right, "Your right images, as many as --left")
                    ->check(CLI::ExistingFile);
  auto* sequence =
      cmd->add_option("--sequence", o->sequence,
                      "A folder of your numbered pairs (NNNN_left.png, NNNN_right.png), in name "
                      "order, instead of --left/--right")
          ->check(CLI::ExistingDirectory);
  sequence->excludes(left)->excludes(right);
  left->needs(right);
  right->needs(left);
  cmd->add_option("--calib", o->set.calib,
                  "The pairs are raw: rectify them with this calibration's grid maps (OpenCV "
                  "FileStorage M1 D1 M2 D2 R T of the frames' size, as scw run --calib reads it)")
      ->check(CLI::ExistingFile);
  cmd->add_option("--engine", o->engine,
                  "rtl: also run the Verilated top and require its results and object table "
                  "to equal the C++ chain's; cpp: the C++ chain only")
      ->check(CLI::IsMember({"cpp", "rtl"}));
  add_set_out_options(cmd, o->out);
  cmd->callback([o, cmd, frames] {
    vec::PipelineSetOptions s = o->set;
    s.height = s.width / 2;
    s.rtl = o->engine == "rtl";
    if (!o->sequence.empty())
      for (const auto& [l, r] : app::find_pairs(o->sequence)) {
        o->left.push_back(l.string());
        o->right.push_back(r.string());
      }
    if (frames->count() > 0 && o->left.size() > static_cast<std::size_t>(s.frames)) {
      o->left.resize(static_cast<std::size_t>(s.frames));
      o->right.resize(static_cast<std::size_t>(s.frames));
    }
    for (const auto& f : o->left) s.left.push_back(host::io::read_grey_image(f));
    for (const auto& f : o->right) s.right.push_back(host::io::read_grey_image(f));
    vec::add_synthetic_frames(s);
    write_set_parts(*cmd, o->out, s.left.size(), [&](const auto& r, const auto& dir) {
      auto part = s;
      part.left = vec::frames_in(s.left, r);
      part.right = vec::frames_in(s.right, r);
      const auto sum = vec::write_pipeline_set(
          part, dir, [](const std::string& line) { std::cout << line << "\n"; });
      std::cout << "wrote " << dir.string() << "/ (" << sum.frames << " frames of " << sum.width
                << "x" << sum.height << ", P = " << sum.ppc << ", " << sum.raw_beats
                << " raw beats a camera, " << sum.object_words << " object words)\n";
    });
  });
}

}  // namespace scw::cli
