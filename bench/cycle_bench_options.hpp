// SPDX-License-Identifier: Apache-2.0
// What the stages' cycle benches share (bench/disparity_cycles, bench/rectify_cycles): their
// options and their --json file.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "host/io/json_file.hpp"
#include "host/io/number_text.hpp"

namespace scw::bench {

/// --ppc (a comma-separated list; `widths` names those the bench is built with, e.g. "1, 2"),
/// --engine rtl|cpp|both and --frames 1 .. 1000, each with its default shown in --help.
inline void add_cycle_options(CLI::App& app, std::vector<int>& ppc, const std::string& widths,
                              std::string& engine, int& frames) {
  app.add_option("--ppc", ppc, "pixels per clock, comma separated (" + widths + ")")
      ->delimiter(',')
      ->capture_default_str();
  app.add_option("--engine", engine, "rtl, cpp or both (both compares them)")
      ->check(CLI::IsMember({"rtl", "cpp", "both"}))
      ->capture_default_str();
  app.add_option("--frames", frames, "frames back to back (>= 2 for a frame period)")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
}

/// --json PATH: every row's record (its member `j`) as one array; nothing when PATH is empty.
template <class Rows>
void write_rows_json(const std::string& path, const Rows& rows) {
  if (path.empty()) return;
  nlohmann::json all = nlohmann::json::array();
  for (const auto& r : rows) all.push_back(r.j);
  host::io::write_json(path, all);
  std::printf("wrote %s\n", path.c_str());
}

}  // namespace scw::bench
