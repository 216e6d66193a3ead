// SPDX-License-Identifier: Apache-2.0
// `scw merge`: joins the output folders of the N shards of one run into what one process would
// have written (docs/slurm.md), after checking that they are all there, once each, and made by
// the same command with the same settings.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace scw::app {

struct MergeReport {
  std::size_t shards = 0, items = 0, files = 0;
  std::string unit;  // what the items are: frames, seeds
};

/// Joins `shards` (output folders, any order) into `out`: the files each manifest names for
/// concatenation are written as the shards' copies one after another in shard order, every
/// other file is copied as it is, shard.json is left out. Throws std::runtime_error naming the
/// problem and its fix when a folder is not a shard, a shard is missing or given twice, the
/// shards disagree on the command, N, the number of items or the settings, two shards wrote
/// one file, or `out` is one of the shards.
MergeReport merge_shards(const std::vector<std::filesystem::path>& shards,
                         const std::filesystem::path& out);

}  // namespace scw::app
