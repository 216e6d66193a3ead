// SPDX-License-Identifier: Apache-2.0
// The stereo pairs `scw run` takes: one pair, or a folder of numbered pairs, read as grey and
// checked for one size.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>

#include "host/app/run.hpp"

namespace scw::app {

using PairFiles = std::pair<std::filesystem::path, std::filesystem::path>;

/// Pairs in a folder: every file whose name holds "left" and has a twin with "right" in its
/// place, in name order (000_left.png / 000_right.png, left_0001.pgm / right_0001.pgm, ...).
/// Throws std::runtime_error when `dir` is not a folder or holds no pair, saying how to name them.
std::vector<PairFiles> find_pairs(const std::filesystem::path& dir);

/// The pairs a run takes: the folder `sequence`'s (find_pairs), or the one pair `left`, `right`.
/// Throws std::runtime_error, naming the options, when both or neither are given.
std::vector<PairFiles> pairs_of(const std::string& left, const std::string& right,
                                const std::string& sequence);

/// "0001_left.png" -> "0001_": what a frame's output files start with in a sequence.
std::string frame_prefix(const std::filesystem::path& left);

/// Reads a pair as grey (io::read_grey_image). Throws std::runtime_error naming both files when
/// they differ in size, or when they differ from `size` (a sequence's first pair) if it is not
/// empty.
std::pair<cv::Mat, cv::Mat> read_pair(const PairFiles& p, cv::Size size = {});

/// Called after each frame with its position, its output and its results.jsonl line.
using FrameDone = std::function<void(std::size_t, const FrameOutput&, const nlohmann::json&)>;

/// A frame's note for progress: its severity and, when an object decided it, the distance
/// ("high at 4.219 m").
std::string frame_note(const FrameOutput& f);

/// Runs `pairs` (all of `size`) through `runner` in order, writing each frame's files
/// (write_frame; prefixed by frame_prefix when there is more than one pair) and its line of
/// results.jsonl into `dir`, which it creates.
void run_pairs(Runner& runner, const std::vector<PairFiles>& pairs, cv::Size size,
               const std::filesystem::path& dir, const FrameDone& done);

}  // namespace scw::app
