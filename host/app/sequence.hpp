// SPDX-License-Identifier: Apache-2.0
// A run over stereo pairs (host/app/pair_files.hpp finds and reads them): each frame's files,
// results.jsonl, and a note for progress.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <string>
#include <utility>
#include <vector>

#include "host/app/frame_files.hpp"
#include "host/app/pair_files.hpp"
#include "host/app/run.hpp"

namespace scw::app {

/// Called after each frame with its position, its output and its results.jsonl line.
using FrameDone = std::function<void(std::size_t, const FrameOutput&, const nlohmann::json&)>;

/// A frame's note for progress: its severity and, when an object decided it, the distance
/// ("high at 4.219 m").
std::string frame_note(const FrameOutput& f);

/// Runs `pairs` (all of `size`) through `runner` in order, writing each frame's files
/// (write_frame with `pictures`; prefixed by frame_prefix when there is more than one pair) and
/// its line of results.jsonl into `dir`, which it creates.
void run_pairs(Runner& runner, const std::vector<PairFiles>& pairs, cv::Size size,
               const std::filesystem::path& dir, const FrameDone& done,
               Pictures pictures = Pictures::kAll);

}  // namespace scw::app
