// SPDX-License-Identifier: Apache-2.0
// frame_note(), run_summary(), run_pairs() (host/app/sequence.hpp).
#include "host/app/sequence.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>
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

std::string run_summary(const RunOptions& run, std::size_t pairs, cv::Size size) {
  const auto& w = run.warning;
  std::ostringstream s;
  s << pairs << (pairs == 1 ? " pair" : " pairs") << ", " << size.width << " x " << size.height
    << " px, f " << w.focal_px << " px, baseline " << w.baseline_m << " m, principal point ("
    << w.cu_px << ", " << w.cv_px << "), window " << run.window << ", d " << run.min_disp << " .. "
    << run.max_disp << ", " << disparity::mode_name(run.mode) << " mode"
    << (run.ground ? ", ground removal" : "");
  return s.str();
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
