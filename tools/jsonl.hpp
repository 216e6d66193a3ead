// SPDX-License-Identifier: Apache-2.0
// One JSON object a line (truth.jsonl, results.jsonl), read whole: the measurement tools trust
// the files scw wrote; `scw eval` (host/eval/records.hpp) is the checked reader for users' files.
#pragma once

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace scw::tools {

inline std::vector<nlohmann::json> read_jsonl(const std::filesystem::path& p) {
  std::ifstream in(p);
  if (!in) throw std::runtime_error("cannot read '" + p.string() + "'");
  std::vector<nlohmann::json> v;
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) v.push_back(nlohmann::json::parse(line));
  return v;
}

}  // namespace scw::tools
