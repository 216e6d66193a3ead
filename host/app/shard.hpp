// SPDX-License-Identifier: Apache-2.0
// Splitting a long run over processes or machines (`--shard I/N`, docs/slurm.md): which frames
// (or seeds) shard I of N takes, and the manifest (shard.json) each shard writes beside its
// results so that `scw merge` can check the shards belong together before joining them.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace scw::app {

/// Shard `index` of `count`, 0-based like SLURM_ARRAY_TASK_ID; {0, 1} is the whole run.
struct Shard {
  int index = 0;
  int count = 1;
};

/// "I/N" (0 <= I < N) -> {I, N}. Throws std::invalid_argument naming the text and the form.
Shard parse_shard(const std::string& text);

/// Items [begin, end) of a run of `total` (frames or seeds).
struct ItemRange {
  std::size_t begin = 0, end = 0;
  std::size_t size() const { return end - begin; }
};

/// Shard I of N takes the contiguous block [floor(I * total / N), floor((I + 1) * total / N)):
/// blocks in order, sizes differing by at most one, every item in exactly one block.
ItemRange shard_range(const Shard& s, std::size_t total);

/// Which frames of a run a process runs and where the run's state restarts. What carries state
/// from frame to frame (scw run's tracker and road stage, scw sim's pipeline, a vector set's
/// stream) cannot start mid-run as if it had seen the frames before it: instead every run
/// restarts its state at the first frame of each of `segments` contiguous blocks (shard_range's
/// rule), and a shard is a whole number of blocks. One process with `segments` N writes exactly
/// what N shards of it write together.
struct SequenceSplit {
  Shard shard;       // the frames run here: shard_range(shard, number of pairs)
  int segments = 0;  // 0: shard.count; otherwise a multiple of shard.count
};

/// The number of segments `split` asks for: `segments`, or N of its shard when 0.
inline int segment_count(const SequenceSplit& split) {
  return split.segments == 0 ? split.shard.count : split.segments;
}

/// The frames [begin, end) a process runs of `frames`, and at which of them it restarts the
/// state. Throws std::invalid_argument when `segments` is not a multiple of the shard count.
struct SplitPlan {
  ItemRange range;
  std::vector<std::size_t> restarts;  // global frame numbers, ascending, the first is range.begin
};
SplitPlan plan_split(const SequenceSplit& split, std::size_t frames);
/// The plan's segments in order: [a restart, the next one or the range's end).
std::vector<ItemRange> segments_of(const SplitPlan& plan);

/// What a shard writes in shard.json: the command, which shard it is, its items, the run's
/// settings (every option but --shard and the output folder) and the files `scw merge` joins
/// by concatenation in shard order (every other file is copied; two shards may not write one).
struct ShardManifest {
  std::string command;
  Shard shard;
  ItemRange range;
  std::size_t total = 0;
  std::string unit = "frames";  // what the items are: frames, seeds
  std::string settings;
  std::vector<std::string> concatenate;
};

/// Writes `dir`/shard.json. Throws std::runtime_error naming the file if it cannot be written.
void write_shard_manifest(const std::filesystem::path& dir, const ShardManifest& m);
/// Reads `dir`/shard.json. Throws std::runtime_error naming the folder when it has none (not a
/// shard's output) or the file is not a manifest.
ShardManifest read_shard_manifest(const std::filesystem::path& dir);

}  // namespace scw::app
