// SPDX-License-Identifier: Apache-2.0
// `scw vectors pipeline`: writes a golden vector set of the whole scw_pipeline top
// (host/vectors/pipeline_set.hpp).
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "host/cli/commands.hpp"
#include "host/io/image_file.hpp"
#include "host/vectors/pipeline_set.hpp"

namespace scw::cli {

namespace vec = scw::vectors;

void add_vectors_pipeline_command(CLI::App& vectors) {
  struct Options {
    vec::PipelineSetOptions set;
    std::vector<std::string> left, right;
    std::string out, engine = "rtl";
  };
  auto o = std::make_shared<Options>();
  auto* cmd = vectors.add_subcommand(
      "pipeline",
      "Write a golden vector set of the scw_pipeline top: raw pairs and knots in, every stream "
      "between the stages and the frame results out");
  cmd->add_option("--config", o->set.config, "Build of the top")
      ->check(CLI::IsMember(vec::pipeline_set_configs()));
  cmd->add_option("--ppc", o->set.ppc, "Pixels per beat")->check(CLI::IsMember({1, 2}));
  cmd->add_option("--frames", o->set.frames, "Synthetic street frames, back to back")
      ->check(CLI::Range(1, 1000));
  cmd->add_option("--size", o->set.width, "Synthetic frames: width (height is half of it)")
      ->check(CLI::IsMember({32, 64}));
  cmd->add_option("--seed", o->set.seed, "Synthetic frames: boxes' textures");
  cmd->add_option("--left", o->left, "Rectified left images (8-bit grey, one size), in order")
      ->check(CLI::ExistingFile);
  cmd->add_option("--right", o->right, "Rectified right images, as many as --left")
      ->check(CLI::ExistingFile);
  cmd->add_option("--engine", o->engine,
                  "rtl: also run the Verilated top and require its results and object table "
                  "to equal the C++ chain's; cpp: the C++ chain only")
      ->check(CLI::IsMember({"cpp", "rtl"}));
  cmd->add_option("--out", o->out, "Vector set directory to write")->required();
  cmd->callback([o] {
    vec::PipelineSetOptions s = o->set;
    s.height = s.width / 2;
    s.rtl = o->engine == "rtl";
    for (const auto& f : o->left) s.left.push_back(host::io::read_grey_image(f));
    for (const auto& f : o->right) s.right.push_back(host::io::read_grey_image(f));
    const auto sum = vec::write_pipeline_set(
        s, o->out, [](const std::string& line) { std::cout << line << "\n"; });
    std::cout << "wrote " << o->out << "/ (" << sum.frames << " frames of " << sum.width << "x"
              << sum.height << ", P = " << sum.ppc << ", " << sum.raw_beats
              << " raw beats a camera, " << sum.object_words << " object words)\n";
  });
}

}  // namespace scw::cli
