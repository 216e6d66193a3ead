// SPDX-License-Identifier: Apache-2.0
// Comparing two runs of the pipeline result by result, and the soak's summary as JSON and text
// (host/soak/soak.hpp).
#include <algorithm>
#include <sstream>

#include "host/soak/soak.hpp"

namespace scw::host::soak {

namespace {

using Words = std::vector<hls::labelling::LabelPacket>;

/// The object words of each frame: every word up to and including the status word (last).
std::vector<Words> per_frame(const Words& table) {
  std::vector<Words> v(1);
  for (const auto& w : table) {
    v.back().push_back(w);
    if (w.last) v.emplace_back();
  }
  v.pop_back();
  return v;
}

std::string describe(const hls::pipeline::PipelineResultPacket& r) {
  const auto& f = r.data.frame;
  std::ostringstream s;
  s << "objects " << f.objects << ", obstacles " << f.obstacles << ", severity "
    << static_cast<int>(f.severity) << ", distance " << f.distance_mm << " mm, flags "
    << r.data.input_error_left << r.data.input_error_right << f.stream_error;
  return s.str();
}

}  // namespace

std::pair<int, std::optional<Divergence>> compare_runs(const RunOutput& cpp, const RunOutput& rtl) {
  const auto a = per_frame(cpp.object_table), b = per_frame(rtl.object_table);
  const std::size_t n = std::max(cpp.results.size(), rtl.results.size());
  int count = 0;
  std::optional<Divergence> first;
  for (std::size_t i = 0; i < n; ++i) {
    std::string what;
    const std::int64_t ca = i < cpp.result_cycles.size() ? cpp.result_cycles[i] : -1;
    const std::int64_t cb = i < rtl.result_cycles.size() ? rtl.result_cycles[i] : -1;
    if (i >= cpp.results.size() || i >= rtl.results.size()) {
      what = i >= rtl.results.size() ? "the RTL gave no result" : "the C++ chain gave no result";
    } else if (cpp.results[i] != rtl.results[i]) {
      what = "result: C++ " + describe(cpp.results[i]) + "; RTL " + describe(rtl.results[i]);
    } else if (ca != cb) {
      what = "result cycle: C++ " + std::to_string(ca) + ", RTL " + std::to_string(cb);
    } else if ((i < a.size()) != (i < b.size()) || (i < a.size() && a[i] != b[i])) {
      what = "object words: C++ " + std::to_string(i < a.size() ? a[i].size() : 0) + ", RTL " +
             std::to_string(i < b.size() ? b[i].size() : 0) + " words, not all equal";
    }
    if (what.empty()) continue;
    ++count;
    if (!first) {
      const std::int64_t c = ca < 0 ? cb : cb < 0 ? ca : std::min(ca, cb);
      first = Divergence{static_cast<int>(i), c, what, ""};
    }
  }
  return {count, first};
}

nlohmann::json SoakOptions::to_json() const {
  return {{"seed", seed}, {"malformed_every", malformed_every}, {"size", {width, height}}};
}

nlohmann::json SoakSummary::to_json() const {
  nlohmann::json j;
  j["frames"] = frames;
  j["results"] = results;
  j["malformed"] = malformed;
  j["divergences"] = divergences;
  j["deadlocks"] = deadlocks;
  j["reference_checked"] = reference_checked;
  j["reference_mismatches"] = reference_mismatches;
  j["reference_boundary"] = reference_boundary;
  j["flag_mismatches"] = flag_mismatches;
  j["content"] = content;
  j["faults"] = faults;
  j["cycles"] = cycles;
  j["seconds"] = {{"cpp", cpp_seconds}, {"rtl", rtl_seconds}, {"reference", reference_seconds}};
  j["passed"] = passed();
  if (first_divergence)
    j["first_divergence"] = {{"frame", first_divergence->frame},
                             {"cycle", first_divergence->cycle},
                             {"what", first_divergence->what},
                             {"fst", first_divergence->fst}};
  if (!first_reference_mismatch.empty()) j["first_reference_mismatch"] = first_reference_mismatch;
  if (!first_reference_boundary.empty()) j["first_reference_boundary"] = first_reference_boundary;
  if (!first_flag_mismatch.empty()) j["first_flag_mismatch"] = first_flag_mismatch;
  if (!deadlock.empty()) j["deadlock"] = deadlock;
  return j;
}

std::string SoakSummary::text() const {
  std::ostringstream s;
  s << "soak: " << frames << " frames (" << malformed << " broken), " << results << " results, "
    << cycles << " cycles: " << divergences << " divergences, " << deadlocks << " deadlocks, "
    << flag_mismatches << " flag mismatches, " << reference_mismatches << " of "
    << reference_checked << " good frames off the floating-point reference (" << reference_boundary
    << " more differ only at a decision boundary)\n";
  if (first_divergence)
    s << "first divergence: result " << first_divergence->frame << " at cycle "
      << first_divergence->cycle << ": " << first_divergence->what
      << (first_divergence->fst.empty() ? "" : "\n  trace: " + first_divergence->fst) << "\n";
  if (!deadlock.empty()) s << "stuck: " << deadlock << "\n";
  if (!first_flag_mismatch.empty()) s << "first flag mismatch: " << first_flag_mismatch << "\n";
  if (!first_reference_boundary.empty())
    s << "first boundary case: " << first_reference_boundary << "\n";
  if (!first_reference_mismatch.empty())
    s << "first reference mismatch: " << first_reference_mismatch << "\n";
  return s.str();
}

}  // namespace scw::host::soak
