// SPDX-License-Identifier: Apache-2.0
// `scw sim`: the whole pipeline clocked in sim/ (host/pipeline/sim_run.hpp); per-stage busy
// time, frame period and latency printed beside the thesis's Table 5.7.
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>

#include "host/cli/commands.hpp"
#include "host/cli/shard_option.hpp"
#include "host/cli/value_checks.hpp"
#include "host/io/json_file.hpp"
#include "host/pipeline/sim_split.hpp"
#include "host/pipeline/sim_text.hpp"

namespace scw::cli {

void add_sim_command(CLI::App& app) {
  struct Options {
    host::pipeline::SimOptions sim;
    std::string json, out_dir, shard;
    int segments = 0;
  };
  auto o = std::make_shared<Options>();
  auto* cmd = app.add_subcommand(
      "sim", "Clock the whole pipeline (frames back to back): busy time per stage, frame period "
             "and latency beside the thesis's Table 5.7 (docs/performance.md)");
  auto& s = o->sim;
  cmd->add_option("--config", s.config, "thesis or small")->capture_default_str();
  cmd->add_option("--ppc", s.ppc, "pixels per beat: 1, 2 or 4")->capture_default_str();
  cmd->add_option("--frames", s.frames, "frames back to back")->capture_default_str();
  cmd->add_option("--engine", s.engine,
                  "cpp: every block's C++ model; rtl: every block Verilated; rtl-top: the "
                  "scw_pipeline top as one Verilated model, faster, its blocks unseen (thesis "
                  "size: build with -DSCW_THESIS_RTL=ON)")
      ->capture_default_str();
  cmd->add_option("--rtl-stages", s.rtl_stages,
                  "with --engine cpp: these blocks Verilated, e.g. labelling,warning")
      ->delimiter(',')
      ->transform(trimmed());
  cmd->add_option("--left", s.left, "left image (default: a synthetic street scene)");
  cmd->add_option("--right", s.right, "right image");
  cmd->add_option("--mode", s.mode, "disparity mode: thesis or opencv")->capture_default_str();
  cmd->add_option("--edge-candidates", s.edge_candidates, disparity::kEdgeCandidatesHelp)
      ->capture_default_str()
      ->check(non_negative("", "8"));
  cmd->add_option("--min-disp", s.dmin, "smallest disparity (default: the configuration's)")
      ->check(non_negative("px", "20"));
  cmd->add_option("--num-disp", s.num_disp, "candidates (default: the configuration's)")
      ->check(positive("", "45"));
  cmd->add_option("--stalls", s.stalls,
                  "input gaps and output backpressure: none, idle, backpressure, both, random:SEED")
      ->capture_default_str();
  cmd->add_option("--json", o->json, "write the measurements as JSON");
  cmd->add_option("--synth-json", s.synth_json,
                  "a `scw synth --json` report of the same --config and --ppc: also give T_P and "
                  "T_L in ms at the estimated Fmax of its slowest module");
  cmd->add_option("--threads", s.threads,
                  "1, or 2: the chain's disparity and road stages step on a second thread, the "
                  "same results clock for clock (engines cpp and rtl; docs/sim.md)")
      ->capture_default_str();
  cmd->add_flag("--reference", s.reference,
                "also run the floating-point chain on the pair and compare the frame result");
  cmd->add_option("--out-dir", o->out_dir,
                  "write frames.jsonl (every frame's cycles and result) and segments.jsonl (each "
                  "segment's timing) here");
  add_shard_option(cmd, o->shard, "frames of --frames")->needs("--out-dir");
  add_segments_option(cmd, o->segments, "the pipeline (a fresh one, clocked from cycle 0)");
  cmd->callback([o, cmd] {
    namespace pipeline = host::pipeline;
    try {
      const app::SequenceSplit split{shard_of(o->shard), o->segments};
      if (!o->json.empty() && pipeline::sim_segments(o->sim, split).size() != 1)
        throw std::invalid_argument(
            "--json writes one run's report; with --segments or --shard "
            "use --out-dir (segments.jsonl has each segment's)");
      if (!o->out_dir.empty()) remove_old_manifest(o->out_dir);
      const auto segments = pipeline::run_sim_split(o->sim, split, std::cerr);
      for (const auto& seg : segments)
        pipeline::print_sim_run(seg.run, seg.frames.begin, std::cout);
      if (!o->json.empty()) {
        host::io::write_json(o->json, pipeline::sim_json(segments.front().run));
        std::cerr << "wrote " << o->json << "\n";
      }
      if (o->out_dir.empty()) return;
      pipeline::write_sim_split(segments, o->out_dir);
      app::ShardManifest m;
      m.total = static_cast<std::size_t>(o->sim.frames);
      m.concatenate = pipeline::sim_split_files();
      write_manifest_if_sharded(o->shard, *cmd, {"out-dir"}, m, o->out_dir);
      std::cerr << "wrote " << o->out_dir << " (frames.jsonl, segments.jsonl)\n";
    } catch (const std::invalid_argument& e) {
      std::cerr << "scw sim: " << e.what() << "\n";
      throw CLI::RuntimeError(2);
    }
  });
}

}  // namespace scw::cli
