// SPDX-License-Identifier: Apache-2.0
// `scw synth`: synthesises every stage and the pipeline top with Yosys at one build and prints
// their resources and worst timing path (host/synth/).
#include <algorithm>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "host/cli/commands.hpp"
#include "host/cli/value_checks.hpp"
#include "host/io/number_text.hpp"
#include "host/synth/builds.hpp"
#include "host/synth/timing.hpp"

namespace scw::cli {
namespace {

namespace syn = host::synth;

using host::io::fixed;

std::vector<std::string> row_of(const syn::Result& r) {
  std::string lv = syn::levels_text(r.levels);
  if (r.levels_from_stages) lv += " (max of stages)";
  const auto f = syn::fmax_mhz(r);
  return {r.run.module,         std::to_string(r.lut), std::to_string(r.ff),
          fixed(syn::bram36(r), 1), std::to_string(r.dsp), lv,
          r.sta_ps ? std::to_string(*r.sta_ps) : "n/a", f ? fixed(*f, 0) : "n/a",
          fixed(r.yosys_s, 1)};
}

void print_table(const syn::BuildRun& b, const std::string& tool,
                 const std::vector<syn::Result>& results) {
  const std::vector<std::string> head = {"module", "LUT",    "FF",     "BRAM36", "DSP",
                                         "levels", "sta ps", "Fmax~",  "Yosys s"};
  std::vector<std::vector<std::string>> rows;
  for (const auto& r : results) {
    rows.push_back(r.ok ? row_of(r) : std::vector<std::string>{r.run.module, "FAILED: " + r.error});
  }
  std::vector<std::size_t> w(head.size());
  for (std::size_t c = 0; c < head.size(); ++c) w[c] = head[c].size();
  for (const auto& row : rows) {
    if (row.size() != head.size()) continue;  // error rows run across the columns
    for (std::size_t c = 0; c < row.size(); ++c) w[c] = std::max(w[c], row[c].size());
  }
  auto print_row = [&](const std::vector<std::string>& row) {
    std::string line;
    for (std::size_t c = 0; c < row.size(); ++c) {
      if (c > 0) line += "  ";
      const std::string pad(
          row.size() == head.size() && row[c].size() < w[c] ? w[c] - row[c].size() : 0, ' ');
      line += c == 0 ? row[c] + pad : pad + row[c];  // names left, numbers right
    }
    std::cout << line << "\n";
  };
  std::cout << "\n" << b.config << " --ppc " << b.ppc << ", " << tool
            << ", xilinx 7-series synth_xilinx\n";
  print_row(head);
  for (const auto& row : rows) print_row(row);
  for (const auto& r : results) {
    if (!r.ok || r.sta_path.empty()) continue;
    std::cout << "worst path of " << r.run.module << ": " << r.sta_path.front().cell << " "
              << r.sta_path.front().net << " -> " << r.sta_path.back().cell << " "
              << r.sta_path.back().net << " (" << r.sta_path.size() << " cells)\n";
  }
  std::cout << "\nBRAM36 = RAMB36 + RAMB18/2. levels: the longest path in cells (ltp -noff). "
               "sta ps: the worst register-to-register path in ps of logic (Yosys sta with the "
               "7-series cell delays, zero routing). Fmax~: with routing taken as "
            << fixed(syn::kRoutingAllowance * 100, 0)
            << " % of the logic delay (docs/timing.md); the path budget is "
            << syn::kStaBudgetPs << " ps.\n";
}

}  // namespace

void add_synth_command(CLI::App& app) {
  auto b = std::make_shared<syn::BuildRun>();
  auto* cmd = app.add_subcommand(
      "synth",
      "Synthesise the stage modules and the pipeline top with Yosys synth_xilinx "
      "(scripts/rtl_synth.sh) at one build of hls/pipeline/pipeline_params.hpp; print the "
      "resources and the worst timing path (Yosys sta) and write them as JSON");
  cmd->add_option("--config", b->config, "Build: " + syn::config_list())->required();
  cmd->add_option("--ppc", b->ppc, "Pixels per clock (beat width)")->capture_default_str();
  cmd->add_option("--json", b->json_out, "Write the results here (JSON)")->required();
  cmd->add_option("--modules", b->modules,
                  "Comma list of modules to synthesise (default all: scw_rectify_map_grid, "
                  "scw_rectify, scw_disparity, scw_labelling, scw_warning, scw_pipeline)")
      ->delimiter(',')
      ->transform(trimmed());
  cmd->add_option("--log-dir", b->log_dir,
                  "Keep each module's Yosys log here (default: the JSON file's folder/synth_logs)");
  cmd->add_option("--scripts", b->scripts,
                  "The repository's scripts/ folder (default: the source tree scw was built from)");
  cmd->add_flag("--ltp-top", b->ltp_top,
                "Measure logic levels on the whole top at the thesis config too (slow)");
  cmd->callback([b] {
    std::string tool;
    std::filesystem::path log_dir;
    const auto results = syn::synthesise_build(*b, tool, log_dir);
    print_table(*b, tool, results);
    std::cout << "\nJSON: " << b->json_out.string() << "\nYosys logs: " << log_dir.string()
              << "\n";
    std::string failed;
    int n_failed = 0;
    for (const auto& r : results) {
      if (r.ok) continue;
      ++n_failed;
      failed += (failed.empty() ? "" : ", ") + r.run.module;
    }
    if (n_failed > 0) {
      throw std::runtime_error(std::to_string(n_failed) + " of " +
                               std::to_string(results.size()) + " modules failed: " + failed);
    }
  });
}

}  // namespace scw::cli
