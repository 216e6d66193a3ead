// SPDX-License-Identifier: Apache-2.0
// parse_shard(), shard_range(), plan_split() and the shard manifest (host/app/shard.hpp).
#include "host/app/shard.hpp"

#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "host/io/json_file.hpp"

namespace scw::app {

namespace fs = std::filesystem;

Shard parse_shard(const std::string& text) {
  const auto bad = [&](const std::string& why) {
    return std::invalid_argument("--shard '" + text + "': " + why +
                                 "; give I/N with 0 <= I < N, e.g. 0/4 (I is 0-based, like "
                                 "SLURM_ARRAY_TASK_ID)");
  };
  const auto slash = text.find('/');
  if (slash == std::string::npos) throw bad("no '/'");
  const auto number = [&](const std::string& s) {
    if (s.empty() || s.size() > 6 || s.find_first_not_of("0123456789") != std::string::npos)
      throw bad("'" + s + "' is not a whole number");
    return std::stoi(s);
  };
  const Shard s{number(text.substr(0, slash)), number(text.substr(slash + 1))};
  if (s.count < 1) throw bad("N must be at least 1");
  if (s.index >= s.count) throw bad("I must be below N");
  return s;
}

ItemRange shard_range(const Shard& s, std::size_t total) {
  const auto at = [&](int i) { return total * static_cast<std::size_t>(i) / s.count; };
  return {at(s.index), at(s.index + 1)};
}

SplitPlan plan_split(const SequenceSplit& split, std::size_t frames) {
  const int segments = segment_count(split);
  if (segments < 1 || segments % split.shard.count != 0)
    throw std::invalid_argument("--segments " + std::to_string(segments) + " with --shard " +
                                std::to_string(split.shard.index) + "/" +
                                std::to_string(split.shard.count) +
                                ": give a multiple of N, so that each shard starts where a "
                                "segment does (e.g. --segments " +
                                std::to_string(split.shard.count) + ")");
  SplitPlan plan{shard_range(split.shard, frames), {}};
  for (int s = 0; s < segments; ++s) {
    const std::size_t start = shard_range({s, segments}, frames).begin;
    if (start >= plan.range.begin && start < plan.range.end &&
        (plan.restarts.empty() || plan.restarts.back() != start))
      plan.restarts.push_back(start);
  }
  return plan;
}

std::vector<ItemRange> segments_of(const SplitPlan& plan) {
  std::vector<ItemRange> segs;
  for (std::size_t i = 0; i < plan.restarts.size(); ++i)
    segs.push_back(
        {plan.restarts[i], i + 1 < plan.restarts.size() ? plan.restarts[i + 1] : plan.range.end});
  return segs;
}

void write_shard_manifest(const fs::path& dir, const ShardManifest& m) {
  const nlohmann::json j = {
      {"command", m.command},   {"shard", m.shard.index}, {"of", m.shard.count},
      {"begin", m.range.begin}, {"end", m.range.end},     {"total", m.total},
      {"unit", m.unit},         {"settings", m.settings}, {"concatenate", m.concatenate}};
  host::io::write_json(dir / "shard.json", j);
}

ShardManifest read_shard_manifest(const fs::path& dir) {
  const fs::path p = dir / "shard.json";
  std::ifstream f(p);
  if (!f)
    throw std::runtime_error("'" + dir.string() +
                             "' holds no shard.json: give the output folders of a command run "
                             "with --shard I/N");
  try {
    const auto j = nlohmann::json::parse(f);
    ShardManifest m;
    m.command = j.at("command").get<std::string>();
    m.shard = {j.at("shard").get<int>(), j.at("of").get<int>()};
    m.range = {j.at("begin").get<std::size_t>(), j.at("end").get<std::size_t>()};
    m.total = j.at("total").get<std::size_t>();
    m.unit = j.at("unit").get<std::string>();
    m.settings = j.at("settings").get<std::string>();
    m.concatenate = j.at("concatenate").get<std::vector<std::string>>();
    return m;
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error("'" + p.string() + "' is not a shard manifest (" + e.what() +
                             "): run the shard again");
  }
}

}  // namespace scw::app
