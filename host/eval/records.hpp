// SPDX-License-Identifier: Apache-2.0
// Reading what `scw eval` compares: truth.jsonl and scene.json from `scw scene`, results.jsonl
// from `scw run`, one frame per line.
#pragma once

#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "hls/warning/warning_params.hpp"

namespace scw::host::eval {

using hls::warning::Severity;

using hls::warning::severity_name;
/// The severity a name stands for (severity_name's inverse); nullopt for any other string.
std::optional<Severity> parse_severity(const std::string& name);

/// One line of truth.jsonl: what the scene renderer knows about a frame.
struct TruthFrame {
  int frame = 0;
  int line = 0;  // 1-based line in the file, for messages
  Severity severity = Severity::kNone;
  std::optional<double> distance_m;  // the deciding object's, from the bumper; none decides
};

/// One line of results.jsonl: what `scw run` made of a frame.
struct ResultFrame {
  int frame = 0;
  int line = 0;
  Severity severity = Severity::kNone;
  std::optional<double> distance_m;  // an upper bound when flags holds too_close
  std::vector<std::string> flags;
  int label = 0;  // the deciding object's number in the frame's label picture; 0: none or absent
};

/// A truth file: its name (for messages), the scene's preset ("" when unknown), its frames in
/// file order.
struct TruthFile {
  std::string name;
  std::string preset;
  std::vector<TruthFrame> frames;
};

/// A results file: its name and its frames in file order.
struct ResultsFile {
  std::string name;
  std::vector<ResultFrame> frames;
};

/// Parses truth.jsonl lines (blank lines skipped). Throws std::runtime_error naming `name`, the
/// line and the field for a line that is not a JSON object, lacks frame, severity or distance_m,
/// holds a wrong type there, or repeats a frame.
TruthFile parse_truth(std::istream& in, const std::string& name);

/// Parses results.jsonl lines: frame, severity, distance_m and flags are required. Throws like
/// parse_truth.
ResultsFile parse_results(std::istream& in, const std::string& name);

/// DIR/truth.jsonl, with the preset from DIR/scene.json when that file exists. `dir` may also
/// name truth.jsonl itself. Throws std::runtime_error for a missing or unreadable file.
TruthFile read_truth(const std::filesystem::path& dir);

/// A results.jsonl file. Throws std::runtime_error for a missing or unreadable file.
ResultsFile read_results(const std::filesystem::path& file);

}  // namespace scw::host::eval
