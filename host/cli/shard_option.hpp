// SPDX-License-Identifier: Apache-2.0
// `--shard I/N` for the commands that split a long run over processes or machines, and the
// manifest each shard writes for `scw merge` (docs/slurm.md).
#pragma once

#include <CLI/CLI.hpp>
#include <cstddef>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "host/app/shard.hpp"

namespace scw::cli {

/// Adds --shard to `cmd`, kept as given in `text` (empty: the whole run, no manifest).
inline CLI::Option* add_shard_option(CLI::App* cmd, std::string& text, const std::string& items) {
  return cmd
      ->add_option("--shard", text,
                   "Run only block I of N of the " + items +
                       " (I 0-based, e.g. $SLURM_ARRAY_TASK_ID/4) and write shard.json for scw "
                       "merge (docs/slurm.md)")
      ->check(CLI::Validator(
          [](std::string& s) {
            try {
              app::parse_shard(s);
              return std::string();
            } catch (const std::invalid_argument& e) {
              return std::string(e.what());
            }
          },
          "I/N", "shard"));
}

/// What `scw soak`'s --shard is refused with when its output cannot be split into blocks that
/// join into one process's (docs/slurm.md, "What does not split").
inline const char* const kSoakNoShard =
    "--shard without --seeds: a soak is one stream, its frames back to back through one Verilated "
    "top under one seeded stall pattern, cycles and the first divergence counted through it, so a "
    "block of its frames is another soak. Split seeds instead: --seeds K --out-dir DIR --shard I/N "
    "(docs/slurm.md)";

/// Adds --segments to `cmd`: where `restarts` (what carries state from frame to frame) restart.
inline CLI::Option* add_segments_option(CLI::App* cmd, int& segments, const std::string& restarts) {
  return cmd
      ->add_option("--segments", segments,
                   "Restart " + restarts +
                       " at the first frame of each of this many blocks (default: N of --shard, "
                       "else 1; docs/slurm.md)")
      ->check(CLI::PositiveNumber);
}

/// The shard `text` names ({0, 1} when empty).
inline app::Shard shard_of(const std::string& text) {
  return text.empty() ? app::Shard{} : app::parse_shard(text);
}

/// Every option given to `cmd`, as CLI11 writes them, but --shard and the `leave_out` ones (the
/// output folder): what must be equal for shards to be one run.
inline std::string shard_settings(const CLI::App& cmd, const std::vector<std::string>& leave_out) {
  std::istringstream all(cmd.config_to_str(false, false));
  std::string settings, line;
  while (std::getline(all, line)) {
    bool keep = line.rfind("shard=", 0) != 0;
    for (const auto& name : leave_out) keep = keep && line.rfind(name + "=", 0) != 0;
    if (keep) settings += line + "\n";
  }
  return settings;
}

/// Removes a shard.json an earlier run left in `dir`: a shard writes its own last, so one that
/// stops half way leaves none and `scw merge` refuses the folder.
inline void remove_old_manifest(const std::filesystem::path& dir) {
  std::filesystem::remove(dir / "shard.json");
}

/// Writes `dir`/shard.json when --shard was given. The caller fills in what only it knows
/// (`m.total`, `m.unit`, `m.concatenate`); `m.command`, `m.shard` and `m.range` come from `cmd`
/// and --shard, `m.settings` from `cmd`'s options but `leave_out`.
inline void write_manifest_if_sharded(const std::string& shard_text, const CLI::App& cmd,
                                      const std::vector<std::string>& leave_out,
                                      app::ShardManifest m, const std::filesystem::path& dir) {
  if (shard_text.empty()) return;
  m.command = cmd.get_name();
  m.shard = app::parse_shard(shard_text);
  m.range = app::shard_range(m.shard, m.total);
  m.settings = shard_settings(cmd, leave_out);
  app::write_shard_manifest(dir, m);
}

}  // namespace scw::cli
