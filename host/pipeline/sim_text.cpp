// SPDX-License-Identifier: Apache-2.0
// print_sim_run() (host/pipeline/sim_text.hpp).
#include "host/pipeline/sim_text.hpp"

#include <iomanip>
#include <string>

#include "host/app/run.hpp"
#include "host/pipeline/thesis_figures.hpp"

namespace scw::host::pipeline {
namespace {

using thesis::ms;

void print_line(std::ostream& out, const char* name, std::int64_t cycles,
                const thesis::ChainTime* t) {
  out << std::left << std::setw(24) << name << std::right << std::setw(12) << cycles
      << std::setw(10) << ms(cycles) << " | ";
  if (t) out << std::setw(15) << t->fpga << std::setw(7) << t->gpu << std::setw(7) << t->cpu;
  out << "\n";
}

void print_timing(const SimRun& r, std::ostream& out) {
  const auto& t = r.timing;
  out << std::fixed << std::setprecision(3) << "\n"
      << r.options.config << " configuration, " << r.width << " x " << r.height << ", window "
      << r.window << ", disparities " << r.dmin << " .. " << r.dmin + r.num_disp - 1 << " ("
      << disparity::mode_name(r.mode) << " mode), P = " << r.ppc << ", engine " << r.engine << ", "
      << thesis::kClockMhz << " MHz\n\n";
  out << std::left << std::setw(24) << "" << std::right << std::setw(12) << "cycles"
      << std::setw(10) << "ms"
      << " | thesis: " << std::setw(7) << "FPGA" << std::setw(7) << "GPU" << std::setw(7) << "CPU"
      << "  (ms, Table 5.7)\n";
  if (t.stages.empty()) out << "(one Verilated top: the blocks inside it are not seen)\n";
  for (const auto& row : thesis::kTable57) {
    if (t.stages.empty()) break;
    std::int64_t busy = 0;
    for (const auto& s : t.stages)
      if (s.name == row.block) busy = s.busy();
    const thesis::ChainTime times{row.cpu, row.gpu, row.fpga};
    print_line(out, row.name, busy, &times);
  }
  print_line(out, "frame period T_P", t.period, &thesis::kPeriodMs);
  print_line(out, "latency T_L, first beat", t.latency_first, &thesis::kLatencyMs);
  print_line(out, "latency T_L, last beat", t.latency_last, nullptr);
  if (r.slowest) {
    const auto ms_at = [&](std::int64_t c) { return c / (r.slowest->fmax_mhz * 1000.0); };
    out << "\nat the estimated Fmax of the slowest module, " << r.slowest->module << " ("
        << r.slowest->sta_ps << " ps of logic, " << std::setprecision(1) << r.slowest->fmax_mhz
        << " MHz, docs/timing.md):" << std::setprecision(3) << " T_P " << ms_at(t.period)
        << " ms, T_L " << ms_at(t.latency_first) << " ms (thesis FPGA: " << thesis::kPeriodMs.fpga
        << " / " << thesis::kLatencyMs.fpga << " ms at 125 MHz)\n";
  }
}

void print_frames(const SimRun& r, std::size_t first_frame, std::ostream& out) {
  const auto& t = r.timing;
  out << "\nbusy = a block's first beat in to its last beat out, last frame; T_P = "
         "between the last two results; T_L = the last frame's.\n";
  if (!t.stages.empty()) {
    out << "every block, per frame (cycles from the first input beat):\n";
    for (const auto& s : t.stages)
      out << "  " << std::left << std::setw(16) << s.name << std::right << std::setw(10)
          << s.first_in << " .. " << std::setw(10) << s.last_out << "\n";
    out << "FIFOs (depth, most held):";
    for (const auto& f : r.report.fifos)
      out << " " << f.name << " " << f.depth << "/" << f.max_occupancy;
    out << "\n";
  }
  for (std::size_t k = 0; k < t.frames.size(); ++k) {
    const auto& f = t.frames[k];
    const auto& res = r.results[k].frame;
    out << "frame " << first_frame + k << ": in " << f.first_in << " .. " << f.last_in
        << ", result " << f.result << ": " << app::severity_name(res.severity) << ", "
        << res.objects << " objects"
        << (res.index != 0xffff ? ", deciding at " + std::to_string(res.distance_mm / 1000.0) + " m"
                                : std::string())
        << "\n";
  }
  if (r.reference) out << r.reference->text() << "\n";
}

}  // namespace

void print_sim_run(const SimRun& r, std::size_t first_frame, std::ostream& out) {
  print_timing(r, out);
  print_frames(r, first_frame, out);
}

}  // namespace scw::host::pipeline
