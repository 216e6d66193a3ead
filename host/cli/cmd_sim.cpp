// SPDX-License-Identifier: Apache-2.0
// `scw sim`: the whole pipeline clocked in sim/ (host/pipeline/sim_run.hpp); per-stage busy
// time, frame period and latency printed beside the thesis's Table 5.7.
#include <iomanip>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>

#include "host/app/run.hpp"
#include "host/cli/commands.hpp"
#include "host/cli/shard_option.hpp"
#include "host/cli/value_checks.hpp"
#include "host/io/json_file.hpp"
#include "host/pipeline/sim_run.hpp"
#include "host/pipeline/thesis_figures.hpp"

namespace scw::cli {
namespace {

namespace thesis = host::pipeline::thesis;
using thesis::ms;

void print_line(const char* name, std::int64_t cycles, const thesis::ChainTime* t) {
  std::cout << std::left << std::setw(24) << name << std::right << std::setw(12) << cycles
            << std::setw(10) << ms(cycles) << " | ";
  if (t) std::cout << std::setw(15) << t->fpga << std::setw(7) << t->gpu << std::setw(7) << t->cpu;
  std::cout << "\n";
}

void print_timing(const host::pipeline::SimRun& r) {
  const auto& t = r.timing;
  std::cout << std::fixed << std::setprecision(3) << "\n"
            << r.options.config << " configuration, " << r.width << " x " << r.height
            << ", window " << r.window << ", disparities " << r.dmin << " .. "
            << r.dmin + r.num_disp - 1 << " (" << disparity::mode_name(r.mode) << " mode), P = "
            << r.ppc << ", engine " << r.engine << ", " << thesis::kClockMhz << " MHz\n\n";
  std::cout << std::left << std::setw(24) << "" << std::right << std::setw(12) << "cycles"
            << std::setw(10) << "ms" << " | thesis: " << std::setw(7) << "FPGA" << std::setw(7)
            << "GPU" << std::setw(7) << "CPU" << "  (ms, Table 5.7)\n";
  if (t.stages.empty()) std::cout << "(one Verilated top: the blocks inside it are not seen)\n";
  for (const auto& row : thesis::kTable57) {
    if (t.stages.empty()) break;
    std::int64_t busy = 0;
    for (const auto& s : t.stages)
      if (s.name == row.block) busy = s.busy();
    const thesis::ChainTime times{row.cpu, row.gpu, row.fpga};
    print_line(row.name, busy, &times);
  }
  print_line("frame period T_P", t.period, &thesis::kPeriodMs);
  print_line("latency T_L, first beat", t.latency_first, &thesis::kLatencyMs);
  print_line("latency T_L, last beat", t.latency_last, nullptr);
  if (r.slowest) {
    const auto ms_at = [&](std::int64_t c) { return c / (r.slowest->fmax_mhz * 1000.0); };
    std::cout << "\nat the estimated Fmax of the slowest module, " << r.slowest->module << " ("
              << r.slowest->sta_ps << " ps of logic, " << std::setprecision(1)
              << r.slowest->fmax_mhz << " MHz, docs/timing.md):" << std::setprecision(3)
              << " T_P " << ms_at(t.period) << " ms, T_L " << ms_at(t.latency_first)
              << " ms (thesis FPGA: " << thesis::kPeriodMs.fpga << " / "
              << thesis::kLatencyMs.fpga << " ms at 125 MHz)\n";
  }
}

void print_frames(const host::pipeline::SimRun& r) {
  const auto& t = r.timing;
  std::cout << "\nbusy = a block's first beat in to its last beat out, last frame; T_P = "
               "between the last two results; T_L = the last frame's.\n";
  if (!t.stages.empty()) {
    std::cout << "every block, per frame (cycles from the first input beat):\n";
    for (const auto& s : t.stages)
      std::cout << "  " << std::left << std::setw(16) << s.name << std::right << std::setw(10)
                << s.first_in << " .. " << std::setw(10) << s.last_out << "\n";
    std::cout << "FIFOs (depth, most held):";
    for (const auto& f : r.report.fifos)
      std::cout << " " << f.name << " " << f.depth << "/" << f.max_occupancy;
    std::cout << "\n";
  }
  for (std::size_t k = 0; k < t.frames.size(); ++k) {
    const auto& f = t.frames[k];
    const auto& res = r.results[k].frame;
    std::cout << "frame " << k << ": in " << f.first_in << " .. " << f.last_in << ", result "
              << f.result << ": " << app::severity_name(res.severity) << ", " << res.objects
              << " objects"
              << (res.index != 0xffff
                      ? ", deciding at " + std::to_string(res.distance_mm / 1000.0) + " m"
                      : std::string())
              << "\n";
  }
  if (r.reference) std::cout << r.reference->text() << "\n";
}

}  // namespace

void add_sim_command(CLI::App& app) {
  struct Options {
    host::pipeline::SimOptions sim;
    std::string json;
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
  add_refused_shard_option(cmd, kSimNoShard);
  cmd->callback([o] {
    try {
      const auto r = host::pipeline::run_sim(o->sim, std::cerr);
      print_timing(r);
      print_frames(r);
      if (!o->json.empty()) {
        host::io::write_json(o->json, host::pipeline::sim_json(r));
        std::cerr << "wrote " << o->json << "\n";
      }
    } catch (const std::invalid_argument& e) {
      std::cerr << "scw sim: " << e.what() << "\n";
      throw CLI::RuntimeError(2);
    }
  });
}

}  // namespace scw::cli
