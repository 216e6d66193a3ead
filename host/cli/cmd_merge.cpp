// SPDX-License-Identifier: Apache-2.0
// `scw merge`: joins the output folders of the shards of one run (`--shard I/N`) into what one
// process would have written (docs/slurm.md).
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "host/app/shard_merge.hpp"
#include "host/cli/commands.hpp"

namespace scw::cli {

namespace {

struct MergeOptions {
  std::vector<std::string> shards;
  std::string out_dir;
};

}  // namespace

void add_merge_command(CLI::App& app) {
  auto o = std::make_shared<MergeOptions>();
  auto* cmd = app.add_subcommand(
      "merge",
      "Join the output folders of the N shards of one run (--shard I/N of scw run, sim, "
      "vectors, soak) into what one process writes; refuses missing, repeated or "
      "mismatched shards");
  cmd->add_option("shards", o->shards, "Every shard's output folder, in any order")->required();
  cmd->add_option("--out-dir", o->out_dir, "Where the joined results go")->required();
  cmd->callback([o] {
    const std::vector<std::filesystem::path> dirs(o->shards.begin(), o->shards.end());
    const auto r = app::merge_shards(dirs, o->out_dir);
    std::cout << "merged " << r.shards << (r.shards == 1 ? " shard" : " shards") << " (" << r.items
              << " " << r.unit << ", " << r.files << " files) into " << o->out_dir << "\n";
  });
}

}  // namespace scw::cli
