// SPDX-License-Identifier: Apache-2.0
// A run over stereo pairs (host/app/pair_files.hpp finds and reads them): each frame's files,
// results.jsonl, and a note for progress; a shard of the pairs and where the state restarts
// (docs/slurm.md).
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <string>
#include <utility>
#include <vector>

#include "host/app/frame_files.hpp"
#include "host/app/pair_files.hpp"
#include "host/app/run.hpp"
#include "host/app/shard.hpp"

namespace scw::app {

/// Called after each frame with the number of frames this process ran before it, its output and
/// its results.jsonl line.
using FrameDone = std::function<void(std::size_t, const FrameOutput&, const nlohmann::json&)>;

/// A frame's note for progress: its severity and, when an object decided it, the distance
/// ("high at 4.219 m").
std::string frame_note(const FrameOutput& f);

/// What a run is about to do, for its first line: the pairs, their size, the camera and the
/// stages' settings ("2 pairs, 1280 x 480 px, f 1400 px, baseline 0.3 m, ...").
std::string run_summary(const RunOptions& run, std::size_t pairs, cv::Size size);

/// A fresh Runner: a new tracker, road stage and engine. A run calls it at each frame where its
/// state restarts.
using RunnerFactory = std::function<std::unique_ptr<Runner>()>;

/// Runs the pairs of `split`'s shard (all of `size`) in order through Runners from `make` (a new
/// one at each restart), writing each frame's files (write_frame with `pictures`; prefixed by
/// frame_prefix when the sequence has more than one pair) and its line of results.jsonl, numbered
/// by its place in the whole sequence, into `dir`, which it creates.
void run_pairs(const RunnerFactory& make, const std::vector<PairFiles>& pairs, cv::Size size,
               const std::filesystem::path& dir, const FrameDone& done,
               Pictures pictures = Pictures::kAll, const SequenceSplit& split = {});

}  // namespace scw::app
