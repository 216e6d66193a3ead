// SPDX-License-Identifier: Apache-2.0
// One Yosys synthesis run of one RTL module: spawns scripts/rtl_synth.sh and parses its summary
// line and the static-timing report it keeps.
#include "host/synth/yosys.hpp"

#include <sys/wait.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <regex>
#include <sstream>
#include <stdexcept>

#include "host/synth/timing.hpp"

namespace scw::host::synth {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::ordered_json;

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

Levels parse_levels(const std::string& s) {
  Levels l;
  std::size_t n = 0;
  while (n < s.size() && std::isdigit(static_cast<unsigned char>(s[n]))) ++n;
  if (n > 0) l.value = std::stoi(s.substr(0, n));
  l.loop = s.find("(loop)") != std::string::npos;
  return l;
}

json levels_json(const Levels& l) { return l.value ? json(*l.value) : json(nullptr); }

/// Fills r from rtl_synth.sh's summary line "<label>: LUT=.. FF=.. ... yosys_s=..".
bool parse_summary(const std::string& out, Result& r) {
  std::istringstream lines(out);
  std::string line;
  while (std::getline(lines, line)) {
    if (line.rfind(r.run.module, 0) != 0) continue;
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
      } else if (k == "sta_ps") {
        if (!v.empty() && std::isdigit(static_cast<unsigned char>(v[0]))) r.sta_ps = std::stoi(v);
      } else if (k == "yosys_s") {
        r.yosys_s = std::stod(v);
      } else {
        const auto* c = std::find_if(std::begin(counts), std::end(counts),
                                     [&](const auto& e) { return k == e.first; });
        if (c == std::end(counts)) {
          --seen;  // sta_from/sta_to (read from the path) or a field added later
        } else {
          *c->second = std::stoi(v);
        }
      }
    }
    return seen >= 10;
  }
  return false;
}

json sta_path_json(const std::vector<StaHop>& path) {
  json a = json::array();
  for (const auto& h : path) a.push_back({{"ps", h.ps}, {"cell", h.cell}, {"net", h.net}});
  return a;
}

}  // namespace

std::string label_of(const ModuleRun& run) {
  std::string s = run.module;
  for (const auto& [k, v] : run.params) s += " " + k + "=" + std::to_string(v);
  return s;
}

double bram36(const Result& r) { return r.ramb36 + r.ramb18 / 2.0; }

std::optional<double> fmax_mhz(const Result& r) {
  if (!r.sta_ps || *r.sta_ps <= 0) return std::nullopt;
  return fmax_mhz_est(*r.sta_ps);
}

std::string levels_text(const Levels& l) {
  if (!l.value) return "n/a";
  return std::to_string(*l.value) + (l.loop ? " (loop)" : "");
}

std::vector<StaHop> parse_sta_path(const std::string& sta_text) {
  // Yosys prints the path from its end: the endpoint "<ps> <cell> (<TYPE>.<pin>)" (or "<ps>
  // (<unknown>)" / "<ps> (<primary output>)", rtl_synth.sh says which it accepts), then for each
  // net going back the net's name and the hop "<ps> <cell> (<TYPE>.<in>-><out>)" that drives it,
  // down to "<ps>   <port> (<primary input>)" when the path starts at an input. Warning lines
  // may come in between.
  static const std::regex hop_re(R"(^\s*(\d+)\s+\S.*\(([A-Za-z0-9_]+\.[^)]*)\)\s*$)");
  static const std::regex end_re(R"(^\s*(\d+)\s+\((<unknown>|<primary output>)\)\s*$)");
  static const std::regex input_re(R"(^\s*(\d+)\s+(\S.*) \(<primary input>\)\s*$)");
  std::vector<StaHop> path;
  std::string pending;  // the last net name read: driven by the next hop
  std::istringstream lines(sta_text);
  std::string line;
  bool on = false;
  while (std::getline(lines, line)) {
    if (!on) {
      on = line.rfind("Latest arrival time in", 0) == 0;
      continue;
    }
    if (line.rfind("Warning:", 0) == 0) continue;
    std::smatch m;
    if (path.empty()) {
      if (!std::regex_match(line, m, hop_re) && !std::regex_match(line, m, end_re)) break;
      path.push_back({std::stoi(m[1].str()), m[2].str(), ""});
      continue;
    }
    if (std::regex_match(line, m, input_re)) {
      path.push_back({std::stoi(m[1].str()), "<primary input>", m[2].str()});
      break;
    }
    if (std::regex_match(line, m, hop_re)) {
      path.push_back({std::stoi(m[1].str()), m[2].str(), pending});
      pending.clear();
      continue;
    }
    const auto first = line.find_first_not_of(" \t");
    if (first == std::string::npos) break;
    pending = line.substr(first);
    if (path.size() == 1 && path[0].net.empty()) path[0].net = pending;  // the endpoint's pin
  }
  // Start first. A path launched by a register starts after the clock tree (the clock's input
  // buffer and BUFG); one from an input port starts at the port.
  std::reverse(path.begin(), path.end());
  const auto bufg = std::find_if(path.begin(), path.end(),
                                 [](const StaHop& h) { return h.cell.rfind("BUFG.", 0) == 0; });
  if (bufg != path.end()) path.erase(path.begin(), bufg + 1);
  return path;
}

fs::path find_script(const std::string& scripts_dir) {
#ifdef SCW_SOURCE_DIR
  const fs::path built_in = fs::path(SCW_SOURCE_DIR) / "scripts";
#else
  const fs::path built_in;
#endif
  const fs::path dir = scripts_dir.empty() ? built_in : fs::path(scripts_dir);
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

Result synthesise(const fs::path& script, const ModuleRun& run, const fs::path& log_dir,
                  const std::string& log_stem, bool no_ltp) {
  Result r;
  r.run = run;
  // rtl_synth.sh reads the RTL next to itself (scripts/..), so the .sv files are looked up there.
  const fs::path root = fs::weakly_canonical(script).parent_path().parent_path();
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
  const fs::path sta_file = log_dir / (log_stem + ".sta.txt");
  const fs::path err_file = log_dir / (log_stem + ".stderr");
  fs::remove(sta_file);
  std::string cmd = "bash " + shell_quote(script.string()) + " " + shell_quote(run.module);
  for (const auto& [k, v] : run.params) cmd += " " + shell_quote(k + "=" + std::to_string(v));
  cmd += " --log " + shell_quote(r.log.string());
  cmd += " --sta-path " + shell_quote(sta_file.string());
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
  r.sta_path = parse_sta_path(read_text(sta_file));
  if (!r.sta_ps || r.sta_path.empty() || r.sta_path.back().ps != *r.sta_ps) {
    r.error = "rtl_synth.sh gave no static-timing path (" + sta_file.string() + ")";
    return r;
  }
  // Warnings (a combinational loop) belong next to the figure they qualify.
  if (!err.empty()) std::cerr << err;
  fs::remove(err_file);
  r.ok = true;
  return r;
}

json result_json(const Result& r) {
  json p = json::object();
  for (const auto& [k, v] : r.run.params) p[k] = v;
  json j = {{"module", r.run.module}, {"params", p}};
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
  j["sta_ps"] = r.sta_ps ? json(*r.sta_ps) : json(nullptr);
  const auto f = fmax_mhz(r);
  j["fmax_mhz_est"] = f ? json(std::round(*f * 10.0) / 10.0) : json(nullptr);
  j["routing_allowance"] = kRoutingAllowance;
  j["sta_path"] = sta_path_json(r.sta_path);
  j["yosys_s"] = r.yosys_s;
  j["log"] = r.log.string();
  return j;
}

}  // namespace scw::host::synth
