// SPDX-License-Identifier: Apache-2.0
// frame_note(), plan_split(), run_pairs() (host/app/sequence.hpp).
#include "host/app/sequence.hpp"

#include <algorithm>
#include <fstream>
#include <stdexcept>

#include "host/app/frame_files.hpp"

namespace scw::app {

namespace fs = std::filesystem;

std::string frame_note(const FrameOutput& f) {
  std::string note = severity_name(f.result.severity);
  if (f.deciding_label > 0)
    note += " at " + std::to_string(f.result.distance_mm / 1000.0).substr(0, 5) + " m";
  return note;
}

SplitPlan plan_split(const SequenceSplit& split, std::size_t frames) {
  const int segments = split.segments == 0 ? split.shard.count : split.segments;
  if (segments < 1 || segments % split.shard.count != 0)
    throw std::invalid_argument("--segments " + std::to_string(segments) + " with --shard " +
                                std::to_string(split.shard.index) + "/" +
                                std::to_string(split.shard.count) +
                                ": give a multiple of N, so that each shard starts where a "
                                "segment does (e.g. --segments " +
                                std::to_string(split.shard.count) + ")");
  SplitPlan plan{shard_range(split.shard, frames), {}};
  for (int s = 0; s < segments; ++s) {
    const std::size_t start = shard_range({s, segments}, frames).begin;
    if (start >= plan.range.begin && start < plan.range.end &&
        (plan.restarts.empty() || plan.restarts.back() != start))
      plan.restarts.push_back(start);
  }
  return plan;
}

void run_pairs(const RunnerFactory& make, const std::vector<PairFiles>& pairs, cv::Size size,
               const fs::path& dir, const FrameDone& done, Pictures pictures,
               const SequenceSplit& split) {
  const SplitPlan plan = plan_split(split, pairs.size());
  fs::create_directories(dir);
  std::ofstream jsonl(dir / "results.jsonl");
  if (!jsonl) throw std::runtime_error("cannot write '" + (dir / "results.jsonl").string() + "'");
  std::unique_ptr<Runner> runner;
  for (std::size_t i = plan.range.begin; i < plan.range.end; ++i) {
    if (!runner || std::binary_search(plan.restarts.begin(), plan.restarts.end(), i))
      runner = make();
    const auto [l, r] = read_pair(pairs[i], size);
    const FrameOutput f = runner->process(l, r);
    write_frame(dir, pairs.size() == 1 ? "" : frame_prefix(pairs[i].first), f, pictures);
    const auto j = frame_json(static_cast<int>(i), f);
    jsonl << j.dump() << "\n";
    if (done) done(i - plan.range.begin, f, j);
  }
  if (!jsonl) throw std::runtime_error("cannot write '" + (dir / "results.jsonl").string() + "'");
}

}  // namespace scw::app
