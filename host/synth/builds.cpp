// SPDX-License-Identifier: Apache-2.0
// The modules of each build (from the Params bundles, so `scw synth`, the C++ chain and the
// Verilated top cannot drift apart) and the run that synthesises them.
#include "host/synth/builds.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <regex>
#include <stdexcept>

#include "hls/pipeline/pipeline_params.hpp"
#include "host/io/json_file.hpp"
#include "host/synth/timing.hpp"
#include "host/synth/top_params.hpp"

namespace scw::host::synth {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::ordered_json;

/// The stage modules and the top at one build.
template <class P>
std::vector<ModuleRun> modules_of() {
  return {
      {"scw_rectify_map_grid",
       {{"Ppc", P::kPpc},
        {"MaxWidthPx", P::kMaxWidthPx},
        {"MaxHeight", P::kMaxHeight},
        {"GridLog2", P::kGridLog2}}},
      {"scw_rectify",
       {{"Ppc", P::kPpc},
        {"MaxWidthPx", P::kMaxWidthPx},
        {"MaxHeight", P::kMaxHeight},
        {"Rows", P::kRectRows}}},
      {"scw_disparity",
       {{"Ppc", P::kPpc},
        {"MaxWidthPx", P::kMaxWidthPx},
        {"MaxHeight", P::kMaxHeight},
        {"Window", P::kWindow},
        {"NumDisp", P::kNumDisp}}},
      {"scw_labelling",
       {{"MaxWidthPx", P::kMaxWidthPx},
        {"MaxHeight", P::kMaxHeight},
        {"MaxTilesX", P::kMaxTilesX},
        {"MaxTilesY", P::kMaxTilesY},
        {"LabelsPerTile", P::kLabelsPerTile},
        {"MaxObjects", P::kMaxObjects},
        {"Lanes", P::kPpc}}},
      {"scw_road",
       {{"Ppc", P::kPpc}, {"MaxWidthPx", P::kMaxWidthPx}, {"MaxHeight", P::kMaxHeight}}},
      {"scw_warning", {{"MaxDisparityPx", P::kMaxDisparityPx}}},
      {kTop, top_params<P>()},
  };
}

std::string yosys_version() {
  const char* env = std::getenv("YOSYS");
  const std::string exe = env && *env ? env : "yosys";
  std::string out;
  if (FILE* p = popen(("'" + exe + "' -V 2>/dev/null").c_str(), "r")) {
    char buf[256];
    while (std::fgets(buf, sizeof buf, p)) out += buf;
    pclose(p);
  }
  std::smatch m;
  static const std::regex re(R"(Yosys\s+(\S.*\S))");
  if (std::regex_search(out, m, re)) return "yosys " + m[1].str();
  return "yosys (version unknown: '" + exe + " -V' failed)";
}

/// The asked modules in the pipeline's order: the top comes last, after the stages whose logic
/// levels it may borrow.
std::vector<ModuleRun> select(const std::vector<ModuleRun>& all,
                              const std::vector<std::string>& wanted) {
  if (wanted.empty()) return all;
  for (const auto& w : wanted) {
    if (std::none_of(all.begin(), all.end(), [&](const ModuleRun& m) { return m.module == w; })) {
      std::string names;
      for (const auto& m : all) names += (names.empty() ? "" : ", ") + m.module;
      throw std::runtime_error("--modules: unknown module '" + w + "'; modules: " + names);
    }
  }
  std::vector<ModuleRun> todo;
  for (const auto& m : all) {
    if (std::find(wanted.begin(), wanted.end(), m.module) != wanted.end()) todo.push_back(m);
  }
  return todo;
}

/// ltp is skipped on the thesis-size top (slower than the synthesis): its level figure is the
/// maximum over the stages of this run.
void borrow_levels(Result& top, const std::vector<Result>& stages) {
  top.levels_from_stages = true;
  for (const auto& s : stages) {
    if (!s.ok) continue;
    top.levels_stages.push_back(s.run.module);
    if (s.levels.value) top.levels.value = std::max(top.levels.value.value_or(0), *s.levels.value);
    if (s.levels_dsp.value) {
      top.levels_dsp.value = std::max(top.levels_dsp.value.value_or(0), *s.levels_dsp.value);
    }
  }
}

}  // namespace

const std::vector<Config>& configs() {
  namespace pl = hls::pipeline;
  static const std::vector<Config> kConfigs = {
      {"thesis", {1, 2, 4}, "minutes at full size",
       [](int p) {
         return p == 1   ? modules_of<pl::ThesisPipeline<1>>()
                : p == 2 ? modules_of<pl::ThesisPipeline<2>>()
                         : modules_of<pl::ThesisPipeline<4>>();
       }},
      {"small", {1, 2, 4}, "seconds to a minute",
       [](int p) {
         return p == 1   ? modules_of<pl::SmallPipeline<1>>()
                : p == 2 ? modules_of<pl::SmallPipeline<2>>()
                         : modules_of<pl::SmallPipeline<4>>();
       }},
      {"tsukuba", {1}, "minutes", [](int) { return modules_of<pl::TsukubaPipeline<1>>(); }},
  };
  return kConfigs;
}

std::string config_list() {
  std::string s;
  for (const auto& c : configs()) {
    if (!s.empty()) s += ", ";
    s += std::string(c.name) + " (--ppc";
    for (std::size_t i = 0; i < c.ppcs.size(); ++i) {
      s += (i ? ", " : " ") + std::to_string(c.ppcs[i]);
    }
    s += ")";
  }
  return s;
}

const Config& find_config(const std::string& name, int ppc) {
  for (const auto& c : configs()) {
    if (name != c.name) continue;
    if (std::find(c.ppcs.begin(), c.ppcs.end(), ppc) == c.ppcs.end()) {
      throw std::runtime_error("config '" + name + "' is not built for --ppc " +
                               std::to_string(ppc) + "; configs: " + config_list());
    }
    return c;
  }
  throw std::runtime_error("unknown config '" + name + "'; configs: " + config_list());
}

std::vector<Result> synthesise_build(const BuildRun& b, std::string& tool_out,
                                     fs::path& log_dir_out) {
  const Config& cfg = find_config(b.config, b.ppc);
  const std::vector<ModuleRun> todo = select(cfg.build(b.ppc), b.modules);
  const fs::path script = find_script(b.scripts);
  if (b.json_out.has_parent_path()) fs::create_directories(b.json_out.parent_path());
  fs::path log_dir = b.log_dir.empty() ? (b.json_out.has_parent_path() ? b.json_out.parent_path()
                                                                        : fs::path(".")) /
                                             "synth_logs"
                                       : b.log_dir;
  fs::create_directories(log_dir);
  // rtl_synth.sh runs Yosys inside its own temporary folder, so a relative --log would land there.
  log_dir = fs::absolute(log_dir).lexically_normal();
  log_dir_out = log_dir;

  tool_out = yosys_version();
  json doc = {{"config", b.config},
              {"ppc", b.ppc},
              {"tool", tool_out},
              {"target", "xilinx 7-series synth_xilinx"},
              {"modules", json::array()}};
  const bool top_no_ltp = b.config == "thesis" && !b.ltp_top;

  std::vector<Result> results;
  for (std::size_t i = 0; i < todo.size(); ++i) {
    const ModuleRun& run = todo[i];
    const bool no_ltp = run.module == kTop && top_no_ltp;
    std::cerr << "[" << i + 1 << "/" << todo.size() << "] " << label_of(run)
              << (no_ltp ? " --no-ltp" : "") << " (" << cfg.duration << ")" << std::endl;
    const auto t0 = std::chrono::steady_clock::now();
    const std::string stem = b.config + "_p" + std::to_string(b.ppc) + "_" + run.module;
    Result r = synthesise(script, run, log_dir, stem, no_ltp);
    const double secs =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    char line[200];
    if (r.ok) {
      std::snprintf(line, sizeof line,
                    "  done in %.1f s: LUT=%d FF=%d BRAM36=%.1f DSP=%d sta=%d ps (%.0f MHz est)",
                    secs, r.lut, r.ff, bram36(r), r.dsp, *r.sta_ps, fmax_mhz(r).value_or(0));
      std::cerr << line << "\n";
    } else {
      std::snprintf(line, sizeof line, "  error after %.1f s: ", secs);
      std::cerr << line << r.error << "\n";
    }
    if (r.ok && no_ltp) borrow_levels(r, results);
    results.push_back(r);
    doc["modules"].push_back(result_json(r));
    io::write_json(b.json_out, doc);
  }
  return results;
}

}  // namespace scw::host::synth

namespace scw::host::synth {

SlowestModule slowest_module(const std::filesystem::path& synth_json, const std::string& config,
                             int ppc) {
  const std::string name = "'" + synth_json.string() + "'";
  std::ifstream in(synth_json);
  if (!in) throw std::runtime_error("cannot read the synthesis report " + name);
  nlohmann::json doc;
  try {
    in >> doc;
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(name + " is not JSON (" + e.what() + "); pass the file that `scw " +
                             "synth --json` wrote");
  }
  if (!doc.is_object() || !doc.contains("modules") || !doc["modules"].is_array()) {
    throw std::runtime_error(name + " has no \"modules\" list: not a `scw synth --json` report");
  }
  const std::string got_config = doc.value("config", std::string("?"));
  const int got_ppc = doc.value("ppc", 0);
  if (got_config != config || got_ppc != ppc) {
    throw std::runtime_error(name + " was made for --config " + got_config + " --ppc " +
                             std::to_string(got_ppc) + ", this run is --config " + config +
                             " --ppc " + std::to_string(ppc) + "; synthesise that build");
  }
  SlowestModule s;
  for (const auto& m : doc["modules"]) {
    const std::string mod = m.value("module", std::string("?"));
    if (m.contains("error")) {
      throw std::runtime_error(name + ": module " + mod + " failed to synthesise (" +
                               m["error"].dump() + ")");
    }
    if (!m.contains("sta_ps") || !m["sta_ps"].is_number_integer()) {
      throw std::runtime_error(name + ": module " + mod +
                               " has no sta_ps (a report from before static timing?)");
    }
    const int ps = m["sta_ps"].get<int>();
    if (ps > s.sta_ps) s = {mod, ps, fmax_mhz_est(ps)};
  }
  if (s.module.empty()) throw std::runtime_error(name + " lists no modules");
  return s;
}

}  // namespace scw::host::synth
