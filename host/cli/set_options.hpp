// SPDX-License-Identifier: Apache-2.0
// The options every `scw vectors <stage>` command shares: how many frames, where the set goes,
// and --shard refused (a set is one stream).
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "host/cli/shard_option.hpp"

namespace scw::cli {

/// --frames K (0, its default: the frames as given).
inline void add_set_frames_option(CLI::App* cmd, int& frames) {
  cmd->add_option("--frames", frames,
                  "K frames back to back: the first K of your inputs (or the preset's), or all "
                  "of them in order, repeated up to K")
      ->check(CLI::Range(1, 100000));
}

/// --out DIR (required) and the refused --shard.
inline void add_set_out_options(CLI::App* cmd, std::string& out) {
  cmd->add_option("--out", out, "Vector set directory to write")->required();
  add_refused_shard_option(cmd, kVectorsNoShard);
}

}  // namespace scw::cli
