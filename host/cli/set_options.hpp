// SPDX-License-Identifier: Apache-2.0
// The options every `scw vectors <stage>` command shares: how many frames, where the set goes,
// and how its frames split into segments and shards (docs/slurm.md), and the loop that writes
// the set, or one set a segment.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
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

/// Where a set goes and how its frames split.
struct SetOut {
  std::string out, shard;
  int segments = 0;
};

/// --out DIR (required), --shard I/N and --segments S.
inline void add_set_out_options(CLI::App* cmd, SetOut& o) {
  cmd->add_option("--out", o.out,
                  "Vector set directory to write (with --segments or --shard: one set a "
                  "segment, in OUT/frames_FIRST-LAST)")
      ->required();
  add_shard_option(cmd, o.shard, "frames");
  add_segments_option(cmd, o.segments, "the stream (a block a set of its own, from reset)");
}

/// Writes the set of `frames` frames (after --frames) into --out, or, split into segments, one set
/// a segment of this shard into OUT/frames_FIRST-LAST (frames numbered in the whole run, 4
/// digits): `write(range, dir)` writes the frames `range` as a set in `dir`. A shard then writes
/// its shard.json (`scw merge` copies the segments' folders).
template <typename Write>
void write_set_parts(const CLI::App& cmd, const SetOut& o, std::size_t frames, Write&& write) {
  const app::SequenceSplit split{shard_of(o.shard), o.segments};
  const auto plan = app::plan_split(split, frames);
  const bool whole = app::segment_count(split) == 1;
  if (!o.shard.empty()) remove_old_manifest(o.out);
  for (const app::ItemRange& r : app::segments_of(plan)) {
    char name[48];
    std::snprintf(name, sizeof name, "frames_%04zu-%04zu", r.begin, r.end - 1);
    if (whole) {
      write(r, std::filesystem::path(o.out));
      continue;
    }
    try {
      write(r, std::filesystem::path(o.out) / name);
    } catch (const std::invalid_argument& e) {  // name the segment: its frames, not the preset's
      throw std::invalid_argument(std::string(name) + ", a segment of " + std::to_string(frames) +
                                  " frames: " + e.what() +
                                  " (give fewer --segments or more --frames)");
    }
  }
  std::filesystem::create_directories(o.out);  // a shard with no frames leaves its folder too
  app::ShardManifest m;
  m.total = frames;
  write_manifest_if_sharded(o.shard, cmd, {"out"}, m, o.out);
}

}  // namespace scw::cli
