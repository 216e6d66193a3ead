// SPDX-License-Identifier: Apache-2.0
// merge_shards() (host/app/shard_merge.hpp).
#include "host/app/shard_merge.hpp"

#include <algorithm>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>

#include "host/app/shard.hpp"

namespace scw::app {

namespace fs = std::filesystem;

namespace {

std::string quoted(const fs::path& p) { return "'" + p.string() + "'"; }

/// The lines of `a` that `b` lacks, joined with "; " ("none" when there are none).
std::string lines_only_in(const std::string& a, const std::string& b) {
  std::istringstream in(a);
  std::set<std::string> theirs;
  {
    std::istringstream other(b);
    for (std::string line; std::getline(other, line);) theirs.insert(line);
  }
  std::string only;
  for (std::string line; std::getline(in, line);)
    if (!theirs.count(line)) only += (only.empty() ? "" : "; ") + line;
  return only.empty() ? "none" : only;
}

/// The shards' manifests by index, checked to be one whole run.
std::vector<std::pair<fs::path, ShardManifest>> check_shards(const std::vector<fs::path>& dirs) {
  if (dirs.empty())
    throw std::runtime_error("no shard folders given: give every shard's --out-dir");
  std::vector<std::pair<fs::path, ShardManifest>> by_index;
  for (const auto& d : dirs) by_index.emplace_back(d, read_shard_manifest(d));
  const auto& [d0, m0] = by_index.front();
  std::map<int, fs::path> seen;
  for (const auto& [d, m] : by_index) {
    // The folders by name: a lambda capturing structured bindings is C++20 (clang 14 refuses).
    const auto differ = [&, first = quoted(d0), this_one = quoted(d)](
                            const std::string& what, const std::string& a, const std::string& b) {
      return std::runtime_error(first + " and " + this_one + " are shards of different runs (" +
                                what + ": " + a + " against " + b +
                                "): merge the shards of one run, made with the same command and "
                                "settings");
    };
    if (m.command != m0.command) throw differ("command", m0.command, m.command);
    if (m.shard.count != m0.shard.count)
      throw differ("N", std::to_string(m0.shard.count), std::to_string(m.shard.count));
    if (m.total != m0.total || m.unit != m0.unit)
      throw differ(m0.unit, std::to_string(m0.total), std::to_string(m.total) + " " + m.unit);
    if (m.settings != m0.settings)
      throw differ("settings", lines_only_in(m0.settings, m.settings),
                   lines_only_in(m.settings, m0.settings));
    if (m.concatenate != m0.concatenate) throw differ("files joined", "one list", "another");
    const auto [at, fresh] = seen.emplace(m.shard.index, d);
    if (!fresh)
      throw std::runtime_error(quoted(at->second) + " and " + quoted(d) + " are both shard " +
                               std::to_string(m.shard.index) + "/" + std::to_string(m.shard.count) +
                               ": give each shard's folder once");
    const ItemRange r = shard_range(m.shard, m.total);
    if (m.range.begin != r.begin || m.range.end != r.end)
      throw std::runtime_error(
          quoted(d) + " holds " + m.unit + " [" + std::to_string(m.range.begin) + ", " +
          std::to_string(m.range.end) + "), not shard " + std::to_string(m.shard.index) + "'s [" +
          std::to_string(r.begin) + ", " + std::to_string(r.end) + "): run that shard again");
  }
  std::string missing;
  for (int i = 0; i < m0.shard.count; ++i)
    if (!seen.count(i)) missing += (missing.empty() ? "" : ", ") + std::to_string(i);
  if (!missing.empty())
    throw std::runtime_error("shard(s) " + missing + " of " + std::to_string(m0.shard.count) +
                             " missing: run them (scw " + m0.command + " ... --shard I/" +
                             std::to_string(m0.shard.count) +
                             ") and give every shard's folder to scw merge");
  std::sort(by_index.begin(), by_index.end(), [](const auto& a, const auto& b) {
    return a.second.shard.index < b.second.shard.index;
  });
  return by_index;
}

/// Regular files under `dir`, relative, in name order (the order is the merge's, not the disk's).
std::vector<fs::path> files_under(const fs::path& dir) {
  std::vector<fs::path> files;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) files.push_back(fs::relative(e.path(), dir));
  std::sort(files.begin(), files.end());
  return files;
}

void append(const fs::path& from, const fs::path& to, bool first) {
  std::ifstream in(from, std::ios::binary);
  std::ofstream o(to,
                  first ? std::ios::binary | std::ios::trunc : std::ios::binary | std::ios::app);
  // An empty shard (no frames) appends nothing: inserting an empty buffer would set failbit.
  if (in && in.peek() != std::ifstream::traits_type::eof()) o << in.rdbuf();
  if (!in || !o) throw std::runtime_error("cannot append " + quoted(from) + " to " + quoted(to));
}

}  // namespace

MergeReport merge_shards(const std::vector<fs::path>& dirs, const fs::path& out) {
  const auto shards = check_shards(dirs);
  for (const auto& [d, m] : shards)
    if (fs::exists(out) && fs::equivalent(d, out))
      throw std::runtime_error("--out-dir " + quoted(out) + " is shard " +
                               std::to_string(m.shard.index) + "'s folder: merge into another");
  fs::create_directories(out);
  const auto& joined = shards.front().second.concatenate;
  MergeReport report{shards.size(), shards.front().second.total, 0, shards.front().second.unit};
  std::map<fs::path, fs::path> copied_from;
  for (std::size_t k = 0; k < shards.size(); ++k) {
    const auto& d = shards[k].first;
    for (const auto& name : joined) {
      if (!fs::is_regular_file(d / name))
        throw std::runtime_error(quoted(d) + " has no " + name +
                                 ": the shard did not finish; run it again");
      append(d / name, out / name, k == 0);
    }
    for (const auto& f : files_under(d)) {
      if (f == "shard.json" || std::count(joined.begin(), joined.end(), f.string())) continue;
      const auto [at, fresh] = copied_from.emplace(f, d);
      if (!fresh)
        throw std::runtime_error(quoted(at->second) + " and " + quoted(d) + " both hold " +
                                 quoted(f) + ": shards write different files; run them again");
      fs::create_directories((out / f).parent_path());
      fs::copy_file(d / f, out / f, fs::copy_options::overwrite_existing);
    }
  }
  report.files = joined.size() + copied_from.size();
  return report;
}

}  // namespace scw::app
