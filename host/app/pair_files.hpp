// SPDX-License-Identifier: Apache-2.0
// Which stereo pairs a run takes: one pair, or a folder of numbered pairs (the sequence folder
// scanner), read as grey and checked for one size. Apart from the run itself so the scanner can be
// fuzzed and reused without the chain.
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <opencv2/core.hpp>

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

}  // namespace scw::app
