// SPDX-License-Identifier: Apache-2.0
// `scw synth`: synthesises every stage and the pipeline top with Yosys (scripts/rtl_synth.sh) at
// one build configuration of hls/pipeline/pipeline_params.hpp and reports the resources.
#include <sys/wait.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "hls/pipeline/pipeline_params.hpp"
#include "host/cli/commands.hpp"

namespace scw::cli {
namespace {

namespace fs = std::filesystem;
// Keys in the order a reader expects (config first, module before its figures).
using json = nlohmann::ordered_json;

constexpr const char* kTop = "scw_pipeline";

/// One synthesis run: an RTL module and its parameters, by the RTL's names.
struct ModuleRun {
  std::string module;
  std::vector<std::pair<std::string, int>> params;
};

/// The five stage modules and the top at one build. Every number comes from the Params bundle,
/// so `scw synth`, the C++ chain and the Verilated top cannot drift apart.
template <class Params>
std::vector<ModuleRun> modules_of() {
  using P = Params;
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
      {"scw_warning", {{"MaxDisparityPx", P::kMaxDisparityPx}}},
      {kTop,
       {{"Ppc", P::kPpc},
        {"MaxWidthPx", P::kMaxWidthPx},
        {"MaxHeight", P::kMaxHeight},
        {"RectRows", P::kRectRows},
        {"GridLog2", P::kGridLog2},
        {"Window", P::kWindow},
        {"NumDisp", P::kNumDisp},
        {"MaxTilesX", P::kMaxTilesX},
        {"MaxTilesY", P::kMaxTilesY},
        {"LabelsPerTile", P::kLabelsPerTile},
        {"MaxObjects", P::kMaxObjects},
        {"MaxDisparityPx", P::kMaxDisparityPx}}},
  };
}

/// A named build and the beat widths it is instantiated for.
struct Config {
  const char* name;
  std::vector<int> ppcs;
  const char* duration;  // what the progress line promises per module
  std::vector<ModuleRun> (*build)(int ppc);
};

const std::vector<Config>& configs() {
  namespace pl = hls::pipeline;
  static const std::vector<Config> kConfigs = {
      {"thesis",
       {1, 2, 4},
       "minutes at full size",
       [](int p) {
         return p == 1   ? modules_of<pl::ThesisPipeline<1>>()
                : p == 2 ? modules_of<pl::ThesisPipeline<2>>()
                         : modules_of<pl::ThesisPipeline<4>>();
       }},
      {"small",
       {1, 2, 4},
       "seconds to a minute",
       [](int p) {
         return p == 1   ? modules_of<pl::SmallPipeline<1>>()
                : p == 2 ? modules_of<pl::SmallPipeline<2>>()
                         : modules_of<pl::SmallPipeline<4>>();
       }},
      {"tsukuba", {1}, "minutes", [](int) { return modules_of<pl::TsukubaPipeline>(); }},
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

/// Single quotes for /bin/sh: the only character that needs care inside them is ' itself.
std::string shell_quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

/// Runs a shell command, returns its standard output and exit status (-1 if it did not exit).
std::pair<std::string, int> run_capture(const std::string& cmd) {
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(cmd.c_str(), "r"), pclose);
  if (!pipe) throw std::runtime_error("cannot start: " + cmd);
  std::string out;
  char buf[4096];
  std::size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, pipe.get())) > 0) out.append(buf, n);
  const int status = pclose(pipe.release());
  return {out, WIFEXITED(status) ? WEXITSTATUS(status) : -1};
}

std::string read_text(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::string tail_lines(const std::string& text, std::size_t n) {
  std::size_t pos = text.size();
  if (pos > 0 && text[pos - 1] == '\n') --pos;
  for (std::size_t k = 0; k < n && pos != std::string::npos && pos > 0; ++k) {
    pos = text.rfind('\n', pos - 1);
  }
  return pos == std::string::npos || pos == 0 ? text : text.substr(pos + 1);
}

/// "Yosys 0.23 (git sha1 ...)" -> "yosys 0.23 (git sha1 ...)": the version the numbers hold for.
std::string yosys_version() {
  const char* env = std::getenv("YOSYS");
  const std::string exe = env && *env ? env : "yosys";
  const auto [out, rc] = run_capture(shell_quote(exe) + " -V 2>/dev/null");
  std::smatch m;
  static const std::regex re(R"(Yosys\s+(\S.*\S))");
  if (rc == 0 && std::regex_search(out, m, re)) return "yosys " + m[1].str();
  return "yosys (version unknown: '" + exe + " -V' failed)";
}

/// The module's file anywhere under rtl_models/ (file name = module name).
std::optional<fs::path> find_sv(const fs::path& root, const std::string& module) {
  const fs::path dir = root / "rtl_models";
  if (!fs::is_directory(dir)) return std::nullopt;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    if (e.is_regular_file() && e.path().filename() == module + ".sv") return e.path();
  }
  return std::nullopt;
}

/// Parameters we would set that the file does not declare: Yosys' chparam would otherwise add
/// them silently and synthesise the module at its defaults, which looks like a result.
std::vector<std::string> undeclared_params(const fs::path& sv, const ModuleRun& run) {
  const std::string text = read_text(sv);
  std::vector<std::string> missing;
  for (const auto& [name, value] : run.params) {
    // "Name = default", allowing the /*verilator public*/ marker in between; a declaration
    // list may share one `parameter` keyword, so the keyword itself is not required.
    const std::regex decl("\\b" + name + "\\b\\s*(/\\*[^*]*\\*/\\s*)?=(?!=)");
    if (!std::regex_search(text, decl)) missing.push_back(name);
  }
  return missing;
}

/// A logic-level figure as rtl_synth.sh prints it: "17", "17(loop)" or "n/a" (ltp skipped).
struct Levels {
  std::optional<int> value;
  bool loop = false;
};

Levels parse_levels(const std::string& s) {
  Levels l;
  std::size_t n = 0;
  while (n < s.size() && std::isdigit(static_cast<unsigned char>(s[n]))) ++n;
  if (n > 0) l.value = std::stoi(s.substr(0, n));
  l.loop = s.find("(loop)") != std::string::npos;
  return l;
}

json levels_json(const Levels& l) { return l.value ? json(*l.value) : json(nullptr); }

/// What one module's run produced: the figures, or an error and where to look.
struct Result {
  ModuleRun run;
  bool ok = false;
  std::string error;
  fs::path log;
  int lut = 0, ff = 0, ramb18 = 0, ramb36 = 0, dsp = 0, lutram = 0, srl = 0;
  Levels levels, levels_dsp;
  bool levels_from_stages = false;
  std::vector<std::string> levels_stages;  // the stages the top's figure is the maximum of
  double yosys_s = 0;
};

double bram36(const Result& r) { return r.ramb36 + r.ramb18 / 2.0; }

json params_json(const ModuleRun& run) {
  json p = json::object();
  for (const auto& [k, v] : run.params) p[k] = v;
  return p;
}

json result_json(const Result& r) {
  json j = {{"module", r.run.module}, {"params", params_json(r.run)}};
  if (!r.ok) {
    j["error"] = r.error;
    if (!r.log.empty()) j["log"] = r.log.string();
    return j;
  }
  j["lut"] = r.lut;
  j["ff"] = r.ff;
  j["ramb18"] = r.ramb18;
  j["ramb36"] = r.ramb36;
  j["bram36"] = bram36(r);
  j["dsp"] = r.dsp;
  j["lutram"] = r.lutram;
  j["srl"] = r.srl;
  j["logic_levels"] = levels_json(r.levels);
  j["logic_levels_dsp_cut"] = levels_json(r.levels_dsp);
  if (r.levels.loop || r.levels_dsp.loop) j["combinational_loop"] = true;
  if (r.levels_from_stages) {
    j["logic_levels_from"] = "stages";
    j["logic_levels_stages"] = r.levels_stages;
  }
  j["yosys_s"] = r.yosys_s;
  j["log"] = r.log.string();
  return j;
}

struct Options {
  std::string config;
  int ppc = 1;
  std::string json_out;
  std::string modules;
  std::string log_dir;
  std::string scripts;
  bool ltp_top = false;
};

std::vector<std::string> split_list(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, ',')) {
    item.erase(0, item.find_first_not_of(" \t"));
    item.erase(item.find_last_not_of(" \t") + 1);
    if (!item.empty()) out.push_back(item);
  }
  return out;
}

fs::path find_script(const Options& o) {
#ifdef SCW_SOURCE_DIR
  const fs::path built_in = fs::path(SCW_SOURCE_DIR) / "scripts";
#else
  const fs::path built_in;
#endif
  const fs::path dir = o.scripts.empty() ? built_in : fs::path(o.scripts);
  const fs::path script = dir / "rtl_synth.sh";
  if (dir.empty() || !fs::is_regular_file(script)) {
    throw std::runtime_error("cannot find rtl_synth.sh" +
                             (dir.empty()
                                  ? std::string(" (this scw was built without SCW_SOURCE_DIR)")
                                  : " in '" + dir.string() + "'") +
                             "; pass --scripts DIR with the repository's scripts/ folder");
  }
  return script;
}

/// Fills r from rtl_synth.sh's summary line "<label>: LUT=.. FF=.. ... yosys_s=..".
bool parse_summary(const std::string& out, Result& r) {
  std::istringstream lines(out);
  std::string line;
  const std::string head = r.run.module;
  while (std::getline(lines, line)) {
    if (line.rfind(head, 0) != 0) continue;
    const auto colon = line.find(": LUT=");
    if (colon == std::string::npos) continue;
    const std::pair<const char*, int*> counts[] = {
        {"LUT", &r.lut}, {"FF", &r.ff},         {"RAMB18", &r.ramb18}, {"RAMB36", &r.ramb36},
        {"DSP", &r.dsp}, {"LUTRAM", &r.lutram}, {"SRL", &r.srl}};
    std::istringstream fields(line.substr(colon + 2));
    std::string f;
    int seen = 0;
    while (fields >> f) {
      const auto eq = f.find('=');
      if (eq == std::string::npos) continue;
      const std::string k = f.substr(0, eq), v = f.substr(eq + 1);
      ++seen;
      if (k == "logic_levels") {
        r.levels = parse_levels(v);
      } else if (k == "logic_levels_dsp_cut") {
        r.levels_dsp = parse_levels(v);
      } else if (k == "yosys_s") {
        r.yosys_s = std::stod(v);
      } else {
        const auto* c = std::find_if(std::begin(counts), std::end(counts),
                                     [&](const auto& e) { return k == e.first; });
        if (c == std::end(counts)) {
          --seen;  // a field added to rtl_synth.sh later: not ours to interpret
        } else {
          *c->second = std::stoi(v);
        }
      }
    }
    return seen >= 10;
  }
  return false;
}

std::string label_of(const ModuleRun& run) {
  std::string s = run.module;
  for (const auto& [k, v] : run.params) s += " " + k + "=" + std::to_string(v);
  return s;
}

Result synthesise(const fs::path& script, const fs::path& root, const ModuleRun& run,
                  const fs::path& log_dir, const std::string& log_stem, bool no_ltp) {
  Result r;
  r.run = run;
  const auto sv = find_sv(root, run.module);
  if (!sv) {
    r.error = "no rtl_models/**/" + run.module + ".sv under '" + root.string() + "'";
    return r;
  }
  if (const auto missing = undeclared_params(*sv, run); !missing.empty()) {
    r.error = fs::relative(*sv, root).string() + " declares no parameter";
    for (const auto& m : missing) r.error += " " + m;
    return r;
  }
  r.log = log_dir / (log_stem + ".log");
  const fs::path err_file = log_dir / (log_stem + ".stderr");
  std::string cmd = "bash " + shell_quote(script.string()) + " " + shell_quote(run.module);
  for (const auto& [k, v] : run.params) cmd += " " + shell_quote(k + "=" + std::to_string(v));
  cmd += " --log " + shell_quote(r.log.string());
  if (no_ltp) cmd += " --no-ltp";
  cmd += " 2> " + shell_quote(err_file.string());
  const auto [out, rc] = run_capture(cmd);
  const std::string err = read_text(err_file);
  if (rc != 0) {
    r.error = "rtl_synth.sh exited with " + std::to_string(rc);
    std::cerr << "  FAILED: " << r.error << "; last lines of its error output:\n"
              << tail_lines(err, 15) << "  log: " << r.log.string() << "\n";
    return r;
  }
  if (!parse_summary(out, r)) {
    r.error = "rtl_synth.sh printed no summary line";
    std::cerr << "  FAILED: " << r.error << "; its output:\n"
              << out << "  log: " << r.log.string() << "\n";
    return r;
  }
  // Warnings (a combinational loop) belong next to the figure they qualify.
  if (!err.empty()) std::cerr << err;
  fs::remove(err_file);
  r.ok = true;
  return r;
}

std::string fixed(double v, int decimals) {
  char b[32];
  std::snprintf(b, sizeof b, "%.*f", decimals, v);
  return b;
}

std::string levels_text(const Levels& l) {
  if (!l.value) return "n/a";
  return std::to_string(*l.value) + (l.loop ? " (loop)" : "");
}

void print_table(const Options& o, const std::string& tool, const std::vector<Result>& results) {
  const std::vector<std::string> head = {"module", "LUT",    "FF",          "BRAM36",
                                         "DSP",    "levels", "levels(DSP)", "Yosys s"};
  std::vector<std::vector<std::string>> rows;
  bool any_from_stages = false;
  for (const auto& r : results) {
    if (!r.ok) {
      rows.push_back({r.run.module, "FAILED: " + r.error});
      continue;
    }
    std::string lv = levels_text(r.levels), lvd = levels_text(r.levels_dsp);
    if (r.levels_from_stages) {
      any_from_stages = true;
      lv += " (max of stages)";
      lvd += " (max of stages)";
    }
    rows.push_back({r.run.module, std::to_string(r.lut), std::to_string(r.ff), fixed(bram36(r), 1),
                    std::to_string(r.dsp), lv, lvd, fixed(r.yosys_s, 1)});
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
  std::cout << "\n"
            << o.config << " --ppc " << o.ppc << ", " << tool << ", xilinx 7-series synth_xilinx\n";
  print_row(head);
  for (const auto& row : rows) print_row(row);
  std::cout << "\nBRAM36 = RAMB36 + RAMB18/2. levels = logic_levels: the longest path in cells "
               "(LUT, CARRY4, MUXF) between flip-flops, block RAMs and ports (ltp -noff).\n"
               "levels(DSP) = logic_levels_dsp_cut: the same path also cut at DSP48E1 blocks, "
               "whose packed pipeline registers ltp cannot see; the register-to-register figure "
               "for designs with multipliers.\n";
  if (any_from_stages) {
    std::cout << "max of stages: ltp was skipped on the top (slow on the whole design; "
                 "--ltp-top runs it), so its figure is the maximum over the stages synthesised "
                 "in this run and does not include the glue between them.\n";
  }
}

void write_json(const fs::path& out, const json& doc) {
  std::ofstream f(out);
  if (!f) throw std::runtime_error("cannot write '" + out.string() + "'");
  f << doc.dump(2) << "\n";
  if (!f) throw std::runtime_error("cannot write '" + out.string() + "'");
}

void run_synth(const Options& o) {
  const Config& cfg = find_config(o.config, o.ppc);
  std::vector<ModuleRun> all = cfg.build(o.ppc);

  std::vector<ModuleRun> todo;
  if (o.modules.empty()) {
    todo = all;
  } else {
    const auto wanted = split_list(o.modules);
    for (const auto& w : wanted) {
      const bool known =
          std::any_of(all.begin(), all.end(), [&](const ModuleRun& m) { return m.module == w; });
      if (!known) {
        std::string names;
        for (const auto& m : all) names += (names.empty() ? "" : ", ") + m.module;
        throw std::runtime_error("--modules: unknown module '" + w + "'; modules: " + names);
      }
    }
    // Keep the pipeline's order whatever order was asked for: the top comes last, after the
    // stages whose logic levels it may borrow.
    for (const auto& m : all) {
      if (std::find(wanted.begin(), wanted.end(), m.module) != wanted.end()) todo.push_back(m);
    }
  }

  const fs::path script = find_script(o);
  // rtl_synth.sh reads the RTL next to itself (scripts/..), so the .sv files are looked up there.
  const fs::path root = fs::weakly_canonical(script).parent_path().parent_path();
  const fs::path out = o.json_out;
  if (out.has_parent_path()) fs::create_directories(out.parent_path());
  fs::path log_dir =
      o.log_dir.empty() ? (out.has_parent_path() ? out.parent_path() : fs::path(".")) / "synth_logs"
                        : fs::path(o.log_dir);
  fs::create_directories(log_dir);
  // rtl_synth.sh runs Yosys inside its own temporary folder, so a relative --log would land there.
  log_dir = fs::absolute(log_dir).lexically_normal();

  const std::string tool = yosys_version();
  json doc = {{"config", o.config},
              {"ppc", o.ppc},
              {"tool", tool},
              {"target", "xilinx 7-series synth_xilinx"},
              {"modules", json::array()}};
  // ltp on the whole thesis-size design takes far longer than the synthesis itself.
  const bool top_no_ltp = o.config == "thesis" && !o.ltp_top;

  std::vector<Result> results;
  for (std::size_t i = 0; i < todo.size(); ++i) {
    const ModuleRun& run = todo[i];
    const bool is_top = run.module == kTop;
    const bool no_ltp = is_top && top_no_ltp;
    std::cerr << "[" << i + 1 << "/" << todo.size() << "] " << label_of(run)
              << (no_ltp ? " --no-ltp" : "") << " (" << cfg.duration << ")" << std::endl;
    const auto t0 = std::chrono::steady_clock::now();
    const std::string stem = o.config + "_p" + std::to_string(o.ppc) + "_" + run.module;
    Result r = synthesise(script, root, run, log_dir, stem, no_ltp);
    const double secs =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (r.ok) {
      std::cerr << "  done in " << fixed(secs, 1) << " s: LUT=" << r.lut << " FF=" << r.ff
                << " BRAM36=" << fixed(bram36(r), 1) << " DSP=" << r.dsp << "\n";
    } else {
      std::cerr << "  error after " << fixed(secs, 1) << " s: " << r.error << "\n";
    }
    if (r.ok && no_ltp) {
      r.levels_from_stages = true;
      for (const auto& s : results) {
        if (!s.ok) continue;
        r.levels_stages.push_back(s.run.module);
        if (s.levels.value) r.levels.value = std::max(r.levels.value.value_or(0), *s.levels.value);
        if (s.levels_dsp.value) {
          r.levels_dsp.value = std::max(r.levels_dsp.value.value_or(0), *s.levels_dsp.value);
        }
      }
    }
    results.push_back(r);
    // Written after every module, so an interrupted thesis-size run keeps what it finished.
    doc["modules"].push_back(result_json(r));
    write_json(out, doc);
  }

  print_table(o, tool, results);
  std::cout << "\nJSON: " << out.string() << "\nYosys logs: " << log_dir.string() << "\n";

  std::string failed;
  int n_failed = 0;
  for (const auto& r : results) {
    if (r.ok) continue;
    ++n_failed;
    failed += (failed.empty() ? "" : ", ") + r.run.module;
  }
  if (n_failed > 0) {
    throw std::runtime_error(std::to_string(n_failed) + " of " + std::to_string(results.size()) +
                             " modules failed: " + failed);
  }
}

}  // namespace

void add_synth_command(CLI::App& app) {
  auto o = std::make_shared<Options>();
  auto* cmd = app.add_subcommand(
      "synth",
      "Synthesise the stage modules and the pipeline top with Yosys synth_xilinx "
      "(scripts/rtl_synth.sh) at one build of hls/pipeline/pipeline_params.hpp; print a "
      "resource table and write it as JSON");
  cmd->add_option("--config", o->config, "Build: " + config_list())->required();
  cmd->add_option("--ppc", o->ppc, "Pixels per clock (beat width)")->capture_default_str();
  cmd->add_option("--json", o->json_out, "Write the results here (JSON)")->required();
  cmd->add_option("--modules", o->modules,
                  "Comma list of modules to synthesise (default all: scw_rectify_map_grid, "
                  "scw_rectify, scw_disparity, scw_labelling, scw_warning, scw_pipeline)");
  cmd->add_option("--log-dir", o->log_dir,
                  "Keep each module's Yosys log here (default: the JSON file's folder/synth_logs)");
  cmd->add_option("--scripts", o->scripts,
                  "The repository's scripts/ folder (default: the source tree scw was built from)");
  cmd->add_flag("--ltp-top", o->ltp_top,
                "Measure logic levels on the whole top at the thesis config too (slow)");
  cmd->callback([o] { run_synth(*o); });
}

}  // namespace scw::cli
