// SPDX-License-Identifier: Apache-2.0
// `scw sim` split into segments and shards (docs/slurm.md): each segment of the frames is a run
// of its own, a fresh pipeline clocked from cycle 0, so one process with `--segments N` writes
// exactly what N shards (`--shard I/N`) write together.
#pragma once

#include <filesystem>
#include <ostream>
#include <vector>

#include "host/app/shard.hpp"
#include "host/pipeline/sim_run.hpp"

namespace scw::host::pipeline {

/// One segment: frames [frames.begin, frames.end) of the whole run, clocked as `run` (whose
/// frames and cycles count from the segment's start).
struct SimSegment {
  app::ItemRange frames;
  SimRun run;
};

/// The segments of `split`'s shard of `o.frames` frames (app::segments_of). Throws
/// std::invalid_argument for fewer than 1 frame and what app::plan_split() throws.
std::vector<app::ItemRange> sim_segments(const SimOptions& o, const app::SequenceSplit& split);

/// Runs sim_segments(), each run_sim() of its frames. Throws what those two throw.
std::vector<SimSegment> run_sim_split(const SimOptions& o, const app::SequenceSplit& split,
                                      std::ostream& log);

/// The files write_sim_split() writes, which `scw merge` joins in shard order.
inline const std::vector<std::string>& sim_split_files() {
  static const std::vector<std::string> files = {"frames.jsonl", "segments.jsonl"};
  return files;
}

/// Writes `dir`/frames.jsonl (a line a frame: its number in the whole run, its segment, its
/// input and result cycles from the segment's start and its result) and `dir`/segments.jsonl
/// (a line a segment: its frames and its sim_json() without the per-frame list). Creates `dir`;
/// throws std::runtime_error naming a file it cannot write.
void write_sim_split(const std::vector<SimSegment>& segments, const std::filesystem::path& dir);

}  // namespace scw::host::pipeline
