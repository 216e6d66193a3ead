// SPDX-License-Identifier: Apache-2.0
// Reading truth.jsonl, scene.json and results.jsonl (docs/eval.md).
#include "host/eval/records.hpp"

#include <climits>
#include <fstream>
#include <functional>
#include <istream>
#include <map>
#include <stdexcept>

#include <nlohmann/json.hpp>

namespace scw::host::eval {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// What to do about a broken line, by file: the remedy is to regenerate it with its writer.
constexpr const char* kTruthFix = "regenerate the folder with scw scene";
constexpr const char* kResultsFix = "run scw run --sequence on the truth's folder again";

/// Where a message points: "'path' line 7".
struct Where {
  const std::string& name;
  int line;
  const char* fix;

  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error("'" + name + "' line " + std::to_string(line) + ": " + what + "; " +
                             fix);
  }
  const json& field(const json& j, const char* key) const {
    const auto it = j.find(key);
    if (it == j.end()) fail(std::string("no \"") + key + "\" field");
    return *it;
  }
};

int frame_of(const json& j, const Where& w) {
  const json& f = w.field(j, "frame");
  if (!f.is_number_integer() || f.get<long long>() < 0 || f.get<long long>() > INT_MAX)
    w.fail("\"frame\" is " + f.dump() + ", not a frame number (0, 1, 2, ...)");
  return static_cast<int>(f.get<long long>());
}

Severity severity_of(const json& j, const Where& w) {
  const json& s = w.field(j, "severity");
  const auto sev = s.is_string() ? parse_severity(s.get<std::string>()) : std::nullopt;
  if (!sev) w.fail("\"severity\" is " + s.dump() + ", not one of none, low, medium, high");
  return *sev;
}

std::optional<double> distance_of(const json& j, const Where& w) {
  const json& d = w.field(j, "distance_m");
  if (d.is_null()) return std::nullopt;
  if (!d.is_number()) w.fail("\"distance_m\" is " + d.dump() + ", not a number of metres or null");
  return d.get<double>();
}

std::vector<std::string> flags_of(const json& j, const Where& w) {
  const json& f = w.field(j, "flags");
  std::vector<std::string> out;
  if (!f.is_array()) w.fail("\"flags\" is " + f.dump() + ", not an array of names");
  for (const auto& e : f) {
    if (!e.is_string()) w.fail("\"flags\" holds " + e.dump() + ", not a name");
    out.push_back(e.get<std::string>());
  }
  return out;
}

/// Calls `take` with every non-blank line as a JSON object, and refuses a frame number seen on
/// an earlier line: matching by frame needs each once.
void for_each_object(std::istream& in, const std::string& name, const char* fix,
                     const std::function<int(const json&, const Where&)>& take) {
  std::map<int, int> first_line;  // frame -> line
  std::string text;
  for (int line = 1; std::getline(in, text); ++line) {
    if (text.find_first_not_of(" \t\r") == std::string::npos) continue;
    const Where w{name, line, fix};
    json j;
    try {
      j = json::parse(text);
    } catch (const json::exception& e) {  // parse_error, or out_of_range for a number too large
      w.fail(std::string("not JSON (") + e.what() + ")");
    }
    if (!j.is_object()) w.fail("not a JSON object");
    int frame = 0;
    try {
      frame = take(j, w);
    } catch (const json::exception& e) {  // a value take()'s checks let through
      w.fail(std::string("a field does not hold what it should (") + e.what() + ")");
    }
    const auto [it, fresh] = first_line.emplace(frame, line);
    if (!fresh)
      w.fail("frame " + std::to_string(frame) + " again (first on line " +
             std::to_string(it->second) + ")");
  }
  if (in.bad()) throw std::runtime_error("cannot read '" + name + "'");
  if (first_line.empty()) throw std::runtime_error("'" + name + "' holds no frames; " + fix);
}

std::ifstream open_file(const fs::path& p, const std::string& what) {
  std::ifstream in(p);
  if (!in) throw std::runtime_error("cannot read '" + p.string() + "': " + what);
  return in;
}

}  // namespace

std::optional<Severity> parse_severity(const std::string& name) {
  for (Severity s : {Severity::kNone, Severity::kLow, Severity::kMedium, Severity::kHigh})
    if (name == severity_name(s)) return s;
  return std::nullopt;
}

TruthFile parse_truth(std::istream& in, const std::string& name) {
  TruthFile t;
  t.name = name;
  for_each_object(in, name, kTruthFix, [&](const json& j, const Where& w) {
    TruthFrame f;
    f.frame = frame_of(j, w);
    f.line = w.line;
    f.severity = severity_of(j, w);
    f.distance_m = distance_of(j, w);
    t.frames.push_back(f);
    return f.frame;
  });
  return t;
}

ResultsFile parse_results(std::istream& in, const std::string& name) {
  ResultsFile r;
  r.name = name;
  for_each_object(in, name, kResultsFix, [&](const json& j, const Where& w) {
    ResultFrame f;
    f.frame = frame_of(j, w);
    f.line = w.line;
    f.severity = severity_of(j, w);
    f.distance_m = distance_of(j, w);
    f.flags = flags_of(j, w);
    if (j.contains("label")) {  // optional: only what surfaces.hpp traces back needs it
      if (!j["label"].is_number_integer() || j["label"].get<int>() < 0)
        w.fail("\"label\" is " + j["label"].dump() + ", not an object number");
      f.label = j["label"].get<int>();
    }
    r.frames.push_back(f);
    return f.frame;
  });
  return r;
}

TruthFile read_truth(const fs::path& dir) {
  const bool is_file = fs::is_regular_file(dir);
  const fs::path file = is_file ? dir : dir / "truth.jsonl";
  auto in = open_file(file, "--truth takes the folder scw scene wrote (truth.jsonl, scene.json)");
  TruthFile t = parse_truth(in, file.string());
  // The preset only titles the report, but a scene.json that is there and broken means the
  // folder is damaged: say so rather than guess.
  const fs::path scene = file.parent_path() / "scene.json";
  if (fs::exists(scene)) {
    auto s = open_file(scene, "it is the scene's description");
    json j;
    try {
      j = json::parse(s);
    } catch (const json::exception& e) {
      throw std::runtime_error("'" + scene.string() + "' is not JSON (" + e.what() + "); " +
                               kTruthFix);
    }
    if (j.is_object() && j.contains("preset") && j["preset"].is_string())
      t.preset = j["preset"].get<std::string>();
  }
  return t;
}

ResultsFile read_results(const fs::path& file) {
  auto in = open_file(file, "--results takes the results.jsonl that scw run wrote");
  return parse_results(in, file.string());
}

}  // namespace scw::host::eval
