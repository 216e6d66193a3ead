// SPDX-License-Identifier: Apache-2.0
// `scw vectors verify|show DIR`: check a golden vector set, or print what it holds.
#include <algorithm>
#include <iomanip>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "host/cli/commands.hpp"
#include "host/vectors/compare_sets.hpp"
#include "host/vectors/vector_set.hpp"

namespace scw::cli {
namespace {

namespace vec = scw::vectors;

// One phrase for a file's shape, e.g. "1024 beats x 18 bits" or "64x32 8UC1"; read_manifest()
// has already checked that the keys exist with the right types.
std::string contents(const vec::FileEntry& f) {
  auto num = [&](const char* key) { return f.meta.at(key).dump(); };
  if (f.kind == "hex") return num("beats") + " beats x " + num("width_bits") + " bits";
  if (f.kind == "csv") return num("rows") + " rows x " + num("columns") + " columns";
  return num("width") + "x" + num("height") + " " + f.meta.at("type").get<std::string>();
}

std::size_t name_width(const vec::Manifest& m) {
  std::size_t w = 4;
  for (const auto& f : m.files) w = std::max(w, f.name.size());
  return w;
}

void run_verify(const std::string& dir) {
  const vec::Manifest m = vec::read_manifest(dir);
  const std::size_t w = name_width(m);
  std::vector<std::string> failed;
  for (const auto& f : m.files) {
    try {
      vec::verify_file(dir, f);
      std::cout << "ok    " << std::left << std::setw(static_cast<int>(w)) << f.name << "  "
                << std::setw(8) << f.role << "  " << std::setw(3) << f.kind << "  " << contents(f)
                << "\n";
    } catch (const std::exception& e) {
      // Keep going: one run should name every broken file, not only the first.
      std::cout << "FAIL  " << e.what() << "\n";
      failed.push_back(f.name);
    }
  }
  const std::size_t n = m.files.size();
  if (failed.empty()) {
    std::cout << "vector set " << dir << " (stage " << m.stage << "): all " << n
              << " files verified\n";
    return;
  }
  std::string names;
  for (const auto& name : failed) names += (names.empty() ? "" : ", ") + name;
  std::cout << "vector set " << dir << " (stage " << m.stage << "): " << failed.size() << " of "
            << n << " files failed\n";
  throw std::runtime_error("vector set '" + dir + "': " + std::to_string(failed.size()) + " of " +
                           std::to_string(n) + " files failed verification (" + names +
                           "); regenerate the set with scw for stage '" + m.stage +
                           "', or restore it from version control");
}

void run_show(const std::string& dir) {
  const vec::Manifest m = vec::read_manifest(dir);
  std::cout << "format:      " << vec::Manifest::kFormat << "\n"
            << "stage:       " << m.stage << "\n"
            << "description: " << m.description << "\n"
            << "config:      " << m.config.dump() << "\n"
            << "files:       " << m.files.size() << " (checksums not verified here; run "
            << "`scw vectors verify`)\n";
  const int w = static_cast<int>(name_width(m));
  std::cout << "  " << std::left << std::setw(w) << "name"
            << "  " << std::setw(8) << "role"
            << "  " << std::setw(4) << "kind"
            << "  " << std::setw(24) << "contents"
            << "  sha256\n";
  for (const auto& f : m.files) {
    std::cout << "  " << std::setw(w) << f.name << "  " << std::setw(8) << f.role << "  "
              << std::setw(4) << f.kind << "  " << std::setw(24) << contents(f) << "  " << f.sha256
              << "\n";
    if (f.kind == "hex" && f.meta.contains("layout"))
      std::cout << "  " << std::string(static_cast<std::size_t>(w), ' ')
                << "  layout: " << f.meta.at("layout").dump() << "\n";
  }
}

std::string joined(const std::vector<std::string>& names) {
  std::string s;
  for (const auto& n : names) s += (s.empty() ? "" : ", ") + n;
  return s;
}

void run_compare(const std::string& a, const std::string& b) {
  const auto c = vec::compare_sets(a, b);
  for (const auto& p : c.problems) std::cout << "DIFFERS  " << p << "\n";
  std::cout << b << " against " << a << ": " << c.same.size() << " files equal byte for byte";
  if (!c.repacked.empty())
    std::cout << "; " << c.repacked.size() << " at another packing, every field equal ("
              << joined(c.repacked)
              << "): a word's layout changed since one set was made; scripts/regen_vectors.sh "
                 "rewrites the committed sets";
  std::cout << "\n";
  if (!c.problems.empty())
    throw std::runtime_error(std::to_string(c.problems.size()) +
                             " of the sets' files or manifest "
                             "entries differ in value (listed above)");
}

}  // namespace

void add_vectors_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand("vectors", "Golden vector sets (manifest + hex/PNG/PGM/CSV)");
  cmd->require_subcommand(1);

  // CLI11 fills the option after add_vectors_command returns, so the string must outlive it.
  auto verify_dir = std::make_shared<std::string>();
  CLI::App* verify = cmd->add_subcommand(
      "verify", "Check the manifest, every file's SHA-256 and each file's shape");
  verify->add_option("dir", *verify_dir, "Vector set directory (holds manifest.json)")
      ->required()
      ->check(CLI::ExistingDirectory);
  verify->callback([verify_dir] { run_verify(*verify_dir); });

  auto show_dir = std::make_shared<std::string>();
  CLI::App* show = cmd->add_subcommand("show", "Print the stage, configuration and file table");
  show->add_option("dir", *show_dir, "Vector set directory (holds manifest.json)")
      ->required()
      ->check(CLI::ExistingDirectory);
  show->callback([show_dir] { run_show(*show_dir); });

  auto pair = std::make_shared<std::vector<std::string>>();
  CLI::App* compare = cmd->add_subcommand(
      "compare",
      "Compare two sets of one preset (e.g. committed and regenerated): byte for byte, or field "
      "by field where a word's layout differs (docs/vectors.md, \"When a width changes\")");
  compare->add_option("dirs", *pair, "The two vector set directories")
      ->required()
      ->expected(2)
      ->check(CLI::ExistingDirectory);
  compare->callback([pair] { run_compare(pair->at(0), pair->at(1)); });
}

}  // namespace scw::cli
