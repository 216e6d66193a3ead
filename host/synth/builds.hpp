// SPDX-License-Identifier: Apache-2.0
// The modules `scw synth` synthesises at each build of hls/pipeline/pipeline_params.hpp, and the
// run over them that writes the JSON report.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "host/synth/yosys.hpp"

namespace scw::host::synth {

inline constexpr const char* kTop = "scw_pipeline";

/// A named build and the beat widths it is instantiated for.
struct Config {
  const char* name;
  std::vector<int> ppcs;
  const char* duration;  // what the progress line promises per module
  std::vector<ModuleRun> (*build)(int ppc);
};

const std::vector<Config>& configs();
/// "thesis (--ppc 1, 2, 4), small (--ppc 1, 2, 4), tsukuba (--ppc 1)".
std::string config_list();
/// The build, or an error naming the builds and their beat widths.
const Config& find_config(const std::string& name, int ppc);

/// What to synthesise and where to write.
struct BuildRun {
  std::string config;
  int ppc = 1;
  std::vector<std::string> modules;  // empty = all; run in the pipeline's order whatever was asked
  std::filesystem::path json_out;
  std::filesystem::path log_dir;  // empty: <json folder>/synth_logs
  std::string scripts;            // rtl_synth.sh's folder, empty: the source tree
  bool ltp_top = false;           // measure logic levels on the thesis-size top too (slow)
};

/// Synthesises the build's modules one by one, printing progress on stderr and rewriting the
/// JSON after every module (an interrupted run keeps what it finished). Returns the results;
/// failed modules are in it with their error.
std::vector<Result> synthesise_build(const BuildRun& b, std::string& tool_out,
                                     std::filesystem::path& log_dir_out);

}  // namespace scw::host::synth

namespace scw::host::synth {

/// The slowest module of a `scw synth --json` report and its estimated Fmax.
struct SlowestModule {
  std::string module;
  int sta_ps = 0;
  double fmax_mhz = 0;
};

/// Reads a `scw synth` JSON report made for `config` and `ppc` and returns its slowest module.
/// Throws, naming the file and what is wrong, if it is unreadable, made for another build, has
/// a failed module or no timing figures.
SlowestModule slowest_module(const std::filesystem::path& synth_json, const std::string& config,
                             int ppc);

}  // namespace scw::host::synth
