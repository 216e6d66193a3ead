// SPDX-License-Identifier: Apache-2.0
// sim_segments(), run_sim_split() and write_sim_split() (host/pipeline/sim_split.hpp).
#include "host/pipeline/sim_split.hpp"

#include <fstream>
#include <stdexcept>
#include <string>

namespace scw::host::pipeline {

namespace fs = std::filesystem;

std::vector<app::ItemRange> sim_segments(const SimOptions& o, const app::SequenceSplit& split) {
  if (o.frames < 1) throw std::invalid_argument("--frames must be at least 1");
  return app::segments_of(app::plan_split(split, static_cast<std::size_t>(o.frames)));
}

std::vector<SimSegment> run_sim_split(const SimOptions& o, const app::SequenceSplit& split,
                                      std::ostream& log) {
  std::vector<SimSegment> segments;
  for (const app::ItemRange& r : sim_segments(o, split)) {
    if (r.size() != static_cast<std::size_t>(o.frames))  // a segment, not the whole run
      log << "frames " << r.begin << " .. " << r.end - 1 << " of " << o.frames
          << ": a fresh pipeline\n";
    SimOptions part = o;
    part.frames = static_cast<int>(r.size());
    segments.push_back({r, run_sim(part, log)});
  }
  return segments;
}

void write_sim_split(const std::vector<SimSegment>& segments, const fs::path& dir) {
  fs::create_directories(dir);
  const fs::path frames_path = dir / "frames.jsonl", segments_path = dir / "segments.jsonl";
  std::ofstream frames(frames_path), segs(segments_path);
  for (std::size_t s = 0; s < segments.size(); ++s) {
    const auto& [range, run] = segments[s];
    nlohmann::json j = sim_json(run);
    const nlohmann::json per_frame = j.at("per_frame");
    j.erase("per_frame");
    j["begin"] = range.begin;
    j["end"] = range.end;
    segs << j.dump() << "\n";
    for (std::size_t k = 0; k < per_frame.size(); ++k) {
      nlohmann::json f = per_frame[k];
      f["frame"] = range.begin + k;
      f["segment_begin"] = range.begin;
      frames << f.dump() << "\n";
    }
  }
  if (!frames) throw std::runtime_error("cannot write '" + frames_path.string() + "'");
  if (!segs) throw std::runtime_error("cannot write '" + segments_path.string() + "'");
}

}  // namespace scw::host::pipeline
