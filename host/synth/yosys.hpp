// SPDX-License-Identifier: Apache-2.0
// One Yosys synthesis run of one RTL module (scripts/rtl_synth.sh): resources and static timing.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace scw::host::synth {

/// One synthesis run: an RTL module and its parameters, by the RTL's names.
struct ModuleRun {
  std::string module;
  std::vector<std::pair<std::string, int>> params;
};

/// "scw_rectify Ppc=1 MaxWidthPx=1280 ...": how progress lines and errors name a run.
std::string label_of(const ModuleRun& run);

/// A logic-level figure as rtl_synth.sh prints it: "17", "17(loop)" or "n/a" (ltp skipped).
struct Levels {
  std::optional<int> value;
  bool loop = false;
};

/// One hop of the worst timing path, start first: the cell's type and the pins it is crossed
/// by ("CARRY4.CI->CO"; the endpoint has one pin, "FDRE.D"; a path from an input port starts at
/// "<primary input>"), the arrival time after it, and the net it drives (for the endpoint, the
/// net at its pin; for an input, the port), by the RTL's name where synthesis kept one.
struct StaHop {
  int ps = 0;
  std::string cell;
  std::string net;
};

/// What one module's run produced: the figures, or an error and where to look.
struct Result {
  ModuleRun run;
  bool ok = false;
  std::string error;
  std::filesystem::path log;
  int lut = 0, ff = 0, ramb18 = 0, ramb36 = 0, dsp = 0, lutram = 0, srl = 0;
  Levels levels, levels_dsp;
  bool levels_from_stages = false;
  std::vector<std::string> levels_stages;  // the stages the top's figure is the maximum of
  std::optional<int> sta_ps;               // worst path, logic only (Yosys sta, zero routing)
  std::vector<StaHop> sta_path;            // that path, start first
  double yosys_s = 0;
};

double bram36(const Result& r);
/// The estimated Fmax of the run's worst path with the routing allowance of timing.hpp.
std::optional<double> fmax_mhz(const Result& r);

/// Where rtl_synth.sh is: `scripts_dir` if given, else the source tree scw was built from.
std::filesystem::path find_script(const std::string& scripts_dir);

/// Runs rtl_synth.sh on `run`, its Yosys log kept as log_dir/<log_stem>.log. Never throws for
/// a failed run: the Result says what failed and where the log is.
Result synthesise(const std::filesystem::path& script, const ModuleRun& run,
                  const std::filesystem::path& log_dir, const std::string& log_stem, bool no_ltp);

/// The JSON entry of one module (resources, logic levels, sta_ps, fmax_mhz_est, sta_path).
nlohmann::ordered_json result_json(const Result& r);

/// Parses Yosys `sta`'s report of the latest path ("Latest arrival time in 'm' is N:" and the
/// hops under it, latest first) into hops, start first. Empty if the text has no such report.
std::vector<StaHop> parse_sta_path(const std::string& sta_text);

/// "17", "17 (loop)" or "n/a".
std::string levels_text(const Levels& l);

}  // namespace scw::host::synth
