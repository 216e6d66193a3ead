// SPDX-License-Identifier: Apache-2.0
// `scw soak`: the small build's Verilated top against the C++ chain over many frames with broken
// frames and random stalls, and reset in mid-frame (host/soak/); a JSON summary, progress on the
// terminal, and the first divergence with an FST trace around it.
#include <filesystem>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>

#include "host/cli/commands.hpp"
#include "host/cli/shard_option.hpp"
#include "host/cli/value_checks.hpp"
#include "host/io/image_file.hpp"
#include "host/io/json_file.hpp"
#include "host/soak/reset_trials.hpp"
#include "host/soak/soak.hpp"

namespace scw::cli {
namespace {

struct SoakOptions {
  std::string config = "small";
  host::soak::SoakOptions soak;
  int resets = 0;
  std::string real_left = "data/tsukuba/scene1.row3.col3.ppm";
  std::string real_right = "data/tsukuba/scene1.row3.col4.ppm";
  std::string json, out_dir, shard;
  int seeds = 0;  // > 0: that many soaks, seeds seed .. seed + K - 1
  bool no_stalls = false;
};

void say(const std::string& line) { std::cerr << line << "\n"; }

/// Runs and prints; false when anything differed.
bool run_soak(SoakOptions& o) {
  if (o.config != "small")
    throw std::invalid_argument("--config " + o.config +
                                ": the soak runs the small build (every block Verilated); give "
                                "--config small");
  auto& s = o.soak;
  s.stalls = !o.no_stalls;
  s.progress = say;
  try {
    s.real.left = host::io::read_grey_image(o.real_left);
    s.real.right = host::io::read_grey_image(o.real_right);
  } catch (const std::exception& e) {
    throw std::invalid_argument(std::string(e.what()) +
                                " (the pair the real crops come from: give --real-left and "
                                "--real-right, or run from the repository's root)");
  }
  const auto summary = host::soak::run_soak(s);
  std::cout << summary.text();
  nlohmann::json j = summary.to_json();
  j.update(s.to_json());
  j["config"] = o.config;
  bool ok = summary.passed();
  if (o.resets > 0) {
    const auto rs = host::soak::run_reset_trials(host::soak::ResetOptions::like(s, o.resets));
    std::cout << "resets: " << rs.trials << " in mid-frame, " << rs.failures << " failed"
              << (rs.first_failure.empty() ? "" : ": first " + rs.first_failure) << "\n";
    j["resets"] = rs.to_json();
    ok = ok && rs.failures == 0;
  }
  if (!o.json.empty()) {
    host::io::write_json(o.json, j);
    std::cerr << "wrote " << o.json << "\n";
  }
  return ok;
}

/// --seeds K: a soak for each seed from --seed on, its summary written to DIR/seed_S.json as
/// --json writes it; --shard I/N runs the block of seeds shard_range gives (docs/slurm.md).
bool run_seeds(SoakOptions& o, const CLI::App& cmd) {
  if (o.out_dir.empty() || !o.json.empty())
    throw std::invalid_argument(
        "--seeds writes each seed's summary to DIR/seed_S.json: give "
        "--out-dir DIR and no --json");
  std::filesystem::create_directories(o.out_dir);
  remove_old_manifest(o.out_dir);
  const std::uint64_t first = o.soak.seed;
  const auto seeds = app::shard_range(shard_of(o.shard), static_cast<std::size_t>(o.seeds));
  bool ok = true;
  for (std::size_t k = seeds.begin; k < seeds.end; ++k) {
    o.soak.seed = first + k;
    o.json = o.out_dir + "/seed_" + std::to_string(o.soak.seed) + ".json";
    ok = run_soak(o) && ok;
  }
  app::ShardManifest m;
  m.total = static_cast<std::size_t>(o.seeds);
  m.unit = "seeds";
  write_manifest_if_sharded(o.shard, cmd, {"out-dir"}, m, o.out_dir);
  return ok;
}

}  // namespace

void add_soak_command(CLI::App& app) {
  auto o = std::make_shared<SoakOptions>();
  auto* cmd = app.add_subcommand(
      "soak", "Many frames through the Verilated pipeline against the C++ chain and the "
              "floating-point reference, with broken frames, random stalls and resets in "
              "mid-frame (docs/soak.md)");
  auto& s = o->soak;
  cmd->add_option("--config", o->config, "the build: small")->capture_default_str();
  cmd->add_option("--frames", s.frames, "frames back to back")
      ->capture_default_str()
      ->check(positive("frames", "1000"));
  cmd->add_option("--malformed-every", s.malformed_every,
                  "a broken frame every K frames (short row, cut frame, sof mid-frame, stray "
                  "beats in turn); 0: none")
      ->capture_default_str()
      ->check(non_negative("frames", "50"));
  cmd->add_option("--seed", s.seed, "content, faults and stalls")->capture_default_str();
  cmd->add_option("--resets", o->resets, "then this many resets at random cycles in mid-frame")
      ->capture_default_str()
      ->check(non_negative("resets", "200"));
  cmd->add_flag("--no-stalls", o->no_stalls, "no input gaps or output backpressure");
  cmd->add_option("--real-left", o->real_left, "the real pair the crops come from: left")
      ->capture_default_str();
  cmd->add_option("--real-right", o->real_right, "and right")->capture_default_str();
  cmd->add_option("--fst", s.fst_dir,
                  "on a divergence, write DIR/pipeline.fst: the top traced around it");
  cmd->add_option("--inject-divergence", s.inject_divergence,
                  "flip a bit of the RTL's result K, to see the checker report it (and trace it)");
  cmd->add_option("--json", o->json, "write the summary as JSON");
  cmd->add_option("--seeds", o->seeds,
                  "K soaks, seeds --seed .. --seed + K - 1, each summary to --out-dir/seed_S.json")
      ->check(positive("soaks", "8"));
  cmd->add_option("--out-dir", o->out_dir, "with --seeds: where the summaries go");
  add_shard_option(cmd, o->shard, "seeds of --seeds K");
  cmd->callback([o, cmd] {
    bool ok = false;
    try {
      if (!o->shard.empty() && o->seeds == 0) throw std::invalid_argument(kSoakNoShard);
      ok = o->seeds > 0 ? run_seeds(*o, *cmd) : run_soak(*o);
    } catch (const std::invalid_argument& e) {
      std::cerr << "scw soak: " << e.what() << "\n";
      throw CLI::RuntimeError(2);
    } catch (const std::runtime_error& e) {
      std::cerr << "scw soak: " << e.what() << "\n";
      throw CLI::RuntimeError(2);
    }
    if (!ok) throw CLI::RuntimeError(1);  // a divergence, deadlock or mismatch: printed above
  });
}

}  // namespace scw::cli
