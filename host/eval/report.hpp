// SPDX-License-Identifier: Apache-2.0
// The outputs of `scw eval` other than the plots: the per-frame table and summary on a stream,
// and the JSON document of --json.
#pragma once

#include <filesystem>
#include <iosfwd>

#include <nlohmann/json.hpp>

#include "host/eval/compare.hpp"

namespace scw::host::eval {

/// One row per frame (true and measured distance, relative error in %, both severities, a mark
/// where they disagree, flags), then the summary with the thesis's 5 % bar beside the largest
/// error.
void print_report(std::ostream& out, const EvalReport& r);

/// frames, frames_with_distance, max_rel_distance_error, mean_rel_distance_error,
/// severity_agreement, severity_truth, severity_measured, per_frame and (when known) preset.
/// Missing values are null.
nlohmann::json report_json(const EvalReport& r);

/// report_json to a file. Throws std::runtime_error when it cannot be written.
void write_report_json(const std::filesystem::path& file, const EvalReport& r);

}  // namespace scw::host::eval
