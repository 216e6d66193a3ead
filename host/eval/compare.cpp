// SPDX-License-Identifier: Apache-2.0
// Truth against `scw run` results (docs/eval.md).
#include "host/eval/compare.hpp"

#include <cmath>
#include <map>
#include <stdexcept>

namespace scw::host::eval {

namespace {

std::string counts(const TruthFile& t, const ResultsFile& r) {
  return "'" + r.name + "' holds " + std::to_string(r.frames.size()) + " frames, '" + t.name +
         "' " + std::to_string(t.frames.size());
}

}  // namespace

EvalReport compare(const TruthFile& truth, const ResultsFile& results) {
  if (truth.frames.empty()) throw std::runtime_error("'" + truth.name + "' holds no frames");
  std::map<int, const ResultFrame*> by_frame;
  for (const auto& r : results.frames) by_frame[r.frame] = &r;
  std::map<int, const TruthFrame*> truth_by_frame;
  for (const auto& t : truth.frames) truth_by_frame[t.frame] = &t;
  // The parsers refuse repeated frames; hand-made inputs are checked here too.
  if (by_frame.size() != results.frames.size())
    throw std::runtime_error("'" + results.name + "' holds a frame number twice");
  if (truth_by_frame.size() != truth.frames.size())
    throw std::runtime_error("'" + truth.name + "' holds a frame number twice");

  // Both directions, so a count mismatch names the first frame the other side lacks.
  for (const auto& [frame, t] : truth_by_frame)
    if (by_frame.count(frame) == 0)
      throw std::runtime_error(counts(truth, results) + ": no result for frame " +
                               std::to_string(frame) + " ('" + truth.name + "' line " +
                               std::to_string(t->line) +
                               "); run scw run --sequence on the truth's folder");
  for (const auto& [frame, r] : by_frame)
    if (truth_by_frame.count(frame) == 0)
      throw std::runtime_error("'" + results.name + "' line " + std::to_string(r->line) +
                               ": frame " + std::to_string(frame) + " is not in the truth (" +
                               counts(truth, results) +
                               "); run scw run --sequence on the truth's folder");

  EvalReport rep;
  rep.preset = truth.preset;
  rep.truth_name = truth.name;
  rep.results_name = results.name;
  double sum_abs = 0.0;
  for (const auto& [frame, t] : truth_by_frame) {
    const ResultFrame& r = *by_frame.at(frame);
    FrameEval f;
    f.frame = frame;
    f.true_severity = t->severity;
    f.measured_severity = r.severity;
    f.agree = t->severity == r.severity;
    f.true_distance_m = t->distance_m;
    f.measured_distance_m = r.distance_m;
    f.flags = r.flags;
    f.label = r.label;
    if (t->distance_m && r.distance_m && *t->distance_m > 0.0) {
      f.rel_error = (*r.distance_m - *t->distance_m) / *t->distance_m;
      const double a = std::abs(*f.rel_error);
      sum_abs += a;
      ++rep.frames_with_distance;
      if (!rep.max_rel_distance_error || a > *rep.max_rel_distance_error) {
        rep.max_rel_distance_error = a;
        rep.max_error_frame = frame;
      }
    }
    rep.severity_disagreements += f.agree ? 0 : 1;
    rep.frames.push_back(std::move(f));
  }
  const auto n = static_cast<double>(rep.frames.size());
  if (rep.frames_with_distance > 0)
    rep.mean_rel_distance_error = sum_abs / rep.frames_with_distance;
  rep.severity_agreement = (n - rep.severity_disagreements) / n;
  return rep;
}

}  // namespace scw::host::eval
