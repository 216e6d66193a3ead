// SPDX-License-Identifier: Apache-2.0
// The comparison of `scw eval`: truth and `scw run` results frame by frame, distance errors
// against the thesis's 5 % bar (Fig. 5.5) and severity agreement (Figs. 5.12, 5.13).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "host/eval/records.hpp"

namespace scw::host::eval {

/// The thesis's bar for the relative distance error: Fig. 5.5 never exceeds 5 % from 30 m to 6 m.
constexpr double kThesisDistanceBar = 0.05;

/// One frame, truth beside measurement.
struct FrameEval {
  int frame = 0;
  Severity true_severity = Severity::kNone;
  Severity measured_severity = Severity::kNone;
  bool agree = true;  // the severities are equal
  std::optional<double> true_distance_m, measured_distance_m;
  /// (measured - true) / true, signed; only when both distances exist and the true one is
  /// positive (a relative error to 0 m has no meaning).
  std::optional<double> rel_error;
  std::vector<std::string> flags;  // the results line's, e.g. too_close, input_error
  int label = 0;                   // the deciding object's number in `scw run`'s label picture
  /// What the deciding object is (surfaces.hpp): "" when not traced (no deciding object, or a
  /// truth folder without its scene), else a kind name, "road" or "sky", and the share of the
  /// object's pixels that see it.
  std::string deciding_surface;
  double surface_share = 0.0;
};

/// Every frame and the summary over them.
struct EvalReport {
  std::string preset;  // the scene's, "" when unknown
  std::string truth_name, results_name;
  std::vector<FrameEval> frames;  // by frame number
  int frames_with_distance = 0;   // frames with a rel_error
  /// Largest and mean |rel_error|; none when no frame has one.
  std::optional<double> max_rel_distance_error, mean_rel_distance_error;
  int max_error_frame = -1;  // where the largest |rel_error| is (-1: none)
  double severity_agreement = 0.0;  // fraction of frames whose severities agree, 0..1
  int severity_disagreements = 0;
  bool surfaces_traced = false;  // deciding_surface was filled in (the scene was at hand)
};

/// Matches frames by number and compares them. Pure: no files. Throws std::runtime_error naming
/// the file and line when a frame of one side is missing from the other (which is also how
/// different frame counts show), and when a side repeats a frame or the truth holds none.
EvalReport compare(const TruthFile& truth, const ResultsFile& results);

}  // namespace scw::host::eval
