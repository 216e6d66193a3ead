// SPDX-License-Identifier: Apache-2.0
// find_pairs(), pairs_of(), frame_prefix(), read_pair() (host/app/pair_files.hpp).
#include "host/app/pair_files.hpp"

#include <algorithm>
#include <stdexcept>

#include "host/io/image_file.hpp"

namespace scw::app {

namespace fs = std::filesystem;

std::vector<PairFiles> find_pairs(const fs::path& dir) {
  if (!fs::is_directory(dir))
    throw std::runtime_error("--sequence '" + dir.string() + "' is not a folder");
  std::vector<fs::path> lefts;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.is_regular_file() && e.path().filename().string().find("left") != std::string::npos)
      lefts.push_back(e.path());
  std::sort(lefts.begin(), lefts.end());
  std::vector<PairFiles> pairs;
  for (const auto& l : lefts) {
    std::string name = l.filename().string();
    name.replace(name.find("left"), 4, "right");
    const fs::path r = l.parent_path() / name;
    if (fs::exists(r)) pairs.emplace_back(l, r);
  }
  if (pairs.empty())
    throw std::runtime_error("--sequence '" + dir.string() +
                             "' holds no pairs: name them like 0001_left.png and 0001_right.png");
  return pairs;
}

std::vector<PairFiles> pairs_of(const std::string& left, const std::string& right,
                                const std::string& sequence) {
  if (!sequence.empty()) {
    if (!left.empty() || !right.empty())
      throw std::runtime_error("give either --left/--right or --sequence, not both");
    return find_pairs(sequence);
  }
  if (left.empty() || right.empty())
    throw std::runtime_error("give --left and --right (or --sequence DIR)");
  return {{left, right}};
}

std::string frame_prefix(const fs::path& left) {
  // "left" is where find_pairs found it, anywhere in the name ("x.left" pairs with "x.right"),
  // so it is taken out of the whole name before the extension goes.
  std::string name = left.filename().string();
  const auto at = name.find("left");
  if (at != std::string::npos) name.erase(at, 4);
  const std::string stem = fs::path(name).stem().string();
  const auto first = stem.find_first_not_of("_-.");
  const auto last = stem.find_last_not_of("_-.");
  return first == std::string::npos ? "frame_" : stem.substr(first, last - first + 1) + "_";
}

std::pair<cv::Mat, cv::Mat> read_pair(const PairFiles& p, cv::Size size) {
  cv::Mat l = host::io::read_grey_image(p.first.string());
  cv::Mat r = host::io::read_grey_image(p.second.string());
  if (l.size() != r.size())
    throw std::runtime_error("'" + p.first.string() + "' (" + std::to_string(l.cols) + " x " +
                             std::to_string(l.rows) + ") and '" + p.second.string() + "' (" +
                             std::to_string(r.cols) + " x " + std::to_string(r.rows) +
                             ") differ in size: a stereo pair has one size");
  if (!size.empty() && l.size() != size)
    throw std::runtime_error("pair '" + p.first.string() + "' differs in size from the first "
                             "pair: every pair of a sequence must have one size");
  return {l, r};
}

}  // namespace scw::app
