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

/// What a command's --shard is refused with when its output cannot be split into blocks that join
/// into one process's (docs/slurm.md, "What does not split").
inline const char* const kSimNoShard =
    "scw sim clocks its frames back to back through one pipeline and reports whole-run timing "
    "(each block's busy span, the frame period between the last two results, the latency, the "
    "FIFOs' fill): a block of the frames is another run with other figures, and no merge of "
    "shards gives one process's. Run scw sim in one process (docs/slurm.md)";
inline const char* const kSoakNoShard =
    "--shard without --seeds: a soak is one stream, its frames back to back through one Verilated "
    "top under one seeded stall pattern, cycles and the first divergence counted through it, so a "
    "block of its frames is another soak. Split seeds instead: --seeds K --out-dir DIR --shard I/N "
    "(docs/slurm.md)";
inline const char* const kVectorsNoShard =
    "a vector set is one stream: each interface's file holds its K frames back to back (the road "
    "and pipeline sets also carry the road from frame to frame), and one manifest records the "
    "frame count and every whole file's SHA-256; scw merge does not rewrite a manifest, so sets "
    "are not split. Make the set in one process (docs/slurm.md)";

/// Adds --shard to a command that cannot be split: any value is refused with `why`.
inline void add_refused_shard_option(CLI::App* cmd, const std::string& why) {
  cmd->add_option_function<std::string>(
         "--shard", [](const std::string&) {}, "Not for this command (docs/slurm.md)")
      ->check(CLI::Validator([why](std::string& s) { return s + " refused: " + why; }, "I/N",
                             "no shard"));
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

/// Writes `dir`/shard.json when --shard was given (`m.shard` set from it, `m.settings` from
/// `cmd`'s options but `leave_out`).
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
