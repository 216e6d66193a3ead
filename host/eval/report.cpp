// SPDX-License-Identifier: Apache-2.0
// The table, summary and JSON of `scw eval` (docs/eval.md).
#include "host/eval/report.hpp"

#include <cstdio>
#include <map>
#include <ostream>
#include <stdexcept>
#include <string>

#include "host/eval/surfaces.hpp"
#include "host/io/json_file.hpp"
#include "host/io/number_text.hpp"

namespace scw::host::eval {

namespace {

using nlohmann::json;

using io::format_number;

std::string metres(const std::optional<double>& m) { return m ? format_number("%.3f", *m) : "-"; }
std::string percent(const std::optional<double>& f) {
  return f ? format_number("%+.2f", 100 * *f) : "-";
}

std::string joined(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& e : v) s += (s.empty() ? "" : ",") + e;
  return s;
}

json or_null(const std::optional<double>& v) { return v ? json(*v) : json(nullptr); }

/// Frames per deciding surface (traced frames only).
std::map<std::string, int> surface_counts(const EvalReport& r) {
  std::map<std::string, int> m;
  for (const auto& f : r.frames)
    if (!f.deciding_surface.empty()) ++m[f.deciding_surface];
  return m;
}

int street_decided(const EvalReport& r) {
  int n = 0;
  for (const auto& f : r.frames) n += is_street_surface(f.deciding_surface);
  return n;
}

}  // namespace

void print_report(std::ostream& out, const EvalReport& r) {
  char row[160];
  out << "eval: " << (r.preset.empty() ? "" : r.preset + ", ") << r.frames.size()
      << " frames; truth '" << r.truth_name << "', results '" << r.results_name << "'\n";
  // The "decided by" column only when the scene was traced (surfaces.hpp).
  auto surface = [&r](const std::string& s) {
    char cell[24];
    std::snprintf(cell, sizeof cell, "%-12s ", s.c_str());
    return r.surfaces_traced ? std::string(cell) : std::string();
  };
  std::snprintf(row, sizeof row, "%6s %11s %12s %13s  %-8s %-9s %s%s\n", "frame", "true D (m)",
                "meas. D (m)", "rel. err (%)", "true", "measured", surface("decided by").c_str(),
                "flags");
  out << row;
  for (const auto& f : r.frames) {
    std::snprintf(row, sizeof row, "%6d %11s %12s %13s  %-8s %-9s %s%s%s\n", f.frame,
                  metres(f.true_distance_m).c_str(), metres(f.measured_distance_m).c_str(),
                  percent(f.rel_error).c_str(), severity_name(f.true_severity),
                  severity_name(f.measured_severity), surface(f.deciding_surface).c_str(),
                  f.agree ? "  " : "* ", joined(f.flags).c_str());
    std::string line(row);
    line.erase(line.find_last_not_of(" \n") + 1);  // no trailing blanks when flags are empty
    out << line << "\n";
  }
  const auto n = r.frames.size();
  out << "(* the severities differ; rel. err = (measured - true) / true)\n";
  out << "frames                 " << n << "\n";
  out << "with both distances    " << r.frames_with_distance << "\n";
  if (r.max_rel_distance_error) {
    out << "max |rel. error|       " << format_number("%.2f %%", 100 * *r.max_rel_distance_error)
        << " at frame " << r.max_error_frame << "   (thesis bar 5 %: "
        << (*r.max_rel_distance_error <= kThesisDistanceBar ? "within" : "above") << ")\n";
    out << "mean |rel. error|      " << format_number("%.2f %%", 100 * *r.mean_rel_distance_error)
        << "\n";
  } else {
    out << "max |rel. error|       - (no frame has both distances; thesis bar 5 %)\n";
  }
  out << "severity agreement     " << n - static_cast<std::size_t>(r.severity_disagreements)
      << " / " << n << " = " << format_number("%.1f %%", 100 * r.severity_agreement) << "\n";
  if (r.surfaces_traced) {
    out << "decided by             ";
    for (const auto& [name, count] : surface_counts(r)) out << name << " " << count << "  ";
    out << "\nby road, kerb or pavement " << street_decided(r) << " frames\n";
  }
}

json report_json(const EvalReport& r) {
  json j;
  j["frames"] = r.frames.size();
  j["frames_with_distance"] = r.frames_with_distance;
  j["max_rel_distance_error"] = or_null(r.max_rel_distance_error);
  j["mean_rel_distance_error"] = or_null(r.mean_rel_distance_error);
  j["severity_agreement"] = r.severity_agreement;
  json truth = json::array(), measured = json::array(), per_frame = json::array();
  for (const auto& f : r.frames) {
    truth.push_back(severity_name(f.true_severity));
    measured.push_back(severity_name(f.measured_severity));
    per_frame.push_back({{"frame", f.frame},
                         {"true_distance_m", or_null(f.true_distance_m)},
                         {"measured_distance_m", or_null(f.measured_distance_m)},
                         {"rel_error", or_null(f.rel_error)},
                         {"true_severity", severity_name(f.true_severity)},
                         {"measured_severity", severity_name(f.measured_severity)},
                         {"agree", f.agree},
                         {"flags", f.flags}});
    if (r.surfaces_traced && !f.deciding_surface.empty()) {
      per_frame.back()["deciding_surface"] = f.deciding_surface;
      per_frame.back()["deciding_surface_share"] = f.surface_share;
    }
  }
  if (r.surfaces_traced) {
    j["decided_by"] = surface_counts(r);
    j["street_decided_frames"] = street_decided(r);
  }
  j["severity_truth"] = truth;
  j["severity_measured"] = measured;
  j["per_frame"] = per_frame;
  if (!r.preset.empty()) j["preset"] = r.preset;
  return j;
}

void write_report_json(const std::filesystem::path& file, const EvalReport& r) {
  io::write_json(file, report_json(r));
}

}  // namespace scw::host::eval
