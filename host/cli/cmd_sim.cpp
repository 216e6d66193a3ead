// SPDX-License-Identifier: Apache-2.0
// `scw sim`: the whole pipeline clocked in sim/ (C++ models, Verilated blocks, or a mix), frames
// back to back; per-stage busy time, frame period and latency beside the thesis's Table 5.7.
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <opencv2/imgproc.hpp>

#include "hls/pipeline/pipeline_params.hpp"
#include "host/app/run.hpp"
#include "host/cli/commands.hpp"
#include "host/disparity/run_model.hpp"
#include "host/io/image_file.hpp"
#include "host/pipeline/reference_chain.hpp"
#include "host/pipeline/setup.hpp"
#include "host/pipeline/synthetic.hpp"
#include "host/synth/builds.hpp"
#include "host/warning/reference.hpp"
#include "sim/builds/pipeline_small_rtl.hpp"
#include "sim/pipeline_chain.hpp"
#if SCW_THESIS_RTL
#include "sim/builds/pipeline_thesis_rtl.hpp"
#endif

namespace scw::cli {
namespace {

constexpr double kClockMhz = 125.0;  // the thesis FPGA's clock (5.5.4)

struct Options {
  std::string config = "thesis";
  int ppc = 1;
  int frames = 3;
  std::string engine = "cpp";
  std::string rtl_stages;  // comma list: these blocks in RTL, the rest in C++
  std::string left, right;
  std::string mode = disparity::mode_name(disparity::kDefaultMode);
  int dmin = -1, num_disp = 0;
  std::string stalls = "none";
  std::string json;
  std::string synth_json;  // a `scw synth --json` report of the same build: ms at its Fmax
  bool reference = false;
};

/// Table 5.7, ms: CPU, GPU, FPGA.
struct ThesisRow {
  const char* name;
  const char* block;  // our block that does that work
  double cpu, gpu, fpga;
};
constexpr ThesisRow kThesis[] = {
    {"stereo rectification", "rectify_left", 3.5, 0.2, 1.0},
    {"disparity map", "disparity", 16.7, 5.4, 6.8},
    {"segmentation", "labelling", 14.1, 3.3, 1.4},
    {"collision warning", "warning", 3.1, 0.7, 0.3},
};
constexpr double kThesisPeriod[3] = {37.4, 9.6, 6.8};   // CPU, GPU, FPGA
constexpr double kThesisLatency[3] = {37.4, 9.6, 9.5};

double ms(std::int64_t cycles) { return static_cast<double>(cycles) / (kClockMhz * 1000.0); }

/// `built`: the blocks the build has as Verilated models (--engine rtl takes those).
sim::PipelineEngines engines_of(const Options& o, const sim::PipelineEngines& built) {
  if (o.engine == "cpp" && o.rtl_stages.empty()) return sim::PipelineEngines::all(sim::Engine::cpp);
  if (o.engine == "rtl") return built;
  if (o.engine != "cpp")
    throw std::invalid_argument("--engine " + o.engine + ": use cpp or rtl (and --rtl-stages)");
  auto e = sim::PipelineEngines::all(sim::Engine::cpp);
  std::stringstream ss(o.rtl_stages);
  std::string b;
  while (std::getline(ss, b, ',')) {
    sim::Engine* slot = b == "check"       ? &e.check
                        : b == "map_grid"  ? &e.map_grid
                        : b == "rectify"   ? &e.rectify
                        : b == "disparity" ? &e.disparity
                        : b == "road"      ? &e.road
                        : b == "labelling" ? &e.labelling
                        : b == "warning"   ? &e.warning
                        : b == "merge"     ? &e.merge
                                           : nullptr;
    if (slot == nullptr)
      throw std::invalid_argument("--rtl-stages: no block '" + b +
                                  "' (check, map_grid, rectify, disparity, road, labelling, "
                                  "warning, merge)");
    *slot = sim::Engine::rtl;
  }
  return e;
}

std::string engine_name(const Options& o) {
  return o.rtl_stages.empty() ? o.engine : "mixed (rtl: " + o.rtl_stages + ")";
}

/// The pair to stream: the user's (converted to grey and resized to the frame) or a synthetic
/// street at the configuration's disparity range.
std::pair<cv::Mat, cv::Mat> input_pair(const Options& o, int w, int h, int dmin, int dmax) {
  if (o.left.empty() != o.right.empty())
    throw std::invalid_argument("give both --left and --right, or neither (synthetic scene)");
  if (o.left.empty()) {
    const auto p = host::pipeline::synthetic_pair(
        w, h, dmin + 2, host::pipeline::street_boxes(w, h, dmin, dmax), 7);
    return {p.left, p.right};
  }
  cv::Mat l = host::io::read_grey_image(o.left), r = host::io::read_grey_image(o.right);
  if (l.size() != r.size())
    throw std::invalid_argument("--left and --right differ in size");
  if (l.cols != w || l.rows != h) {
    std::cerr << "resizing the pair from " << l.cols << " x " << l.rows << " to the "
              << o.config << " frame, " << w << " x " << h << "\n";
    cv::resize(l, l, cv::Size(w, h), 0, 0, cv::INTER_AREA);
    cv::resize(r, r, cv::Size(w, h), 0, 0, cv::INTER_AREA);
  }
  return {l, r};
}

template <typename Build, typename Rtl>
int run(const Options& o, int width, int height, int dmin_default, int num_disp_default,
        const sim::PipelineEngines& built = sim::PipelineEngines::all(sim::Engine::rtl)) {
  constexpr int P = Build::kPpc;
  // Read before the run, so a wrong report fails in a second, not after minutes of simulation.
  std::optional<host::synth::SlowestModule> slow;
  if (!o.synth_json.empty()) slow = host::synth::slowest_module(o.synth_json, o.config, P);
  host::pipeline::StageOptions so;
  so.mode = disparity::mode_from_name(o.mode);
  so.dmin = o.dmin >= 0 ? o.dmin : dmin_default;
  so.num_disp = o.num_disp > 0 ? o.num_disp : num_disp_default;
  so.tiles_x = Build::kMaxTilesX;
  so.tiles_y = Build::kMaxTilesY;
  so.min_area = std::max(20, width * height / 2000);
  const auto [l, r] = input_pair(o, width, height, so.dmin, so.dmin + so.num_disp - 1);
  auto setup = host::pipeline::make_setup(
      width, height, Build::kGridLog2, so, host::pipeline::identity_knots(width, height, Build::kGridLog2),
      host::pipeline::identity_knots(width, height, Build::kGridLog2), 1);
  std::vector<cv::Mat> ls(static_cast<std::size_t>(o.frames), l), rs(static_cast<std::size_t>(o.frames), r);
  const auto pattern = sim::StallPattern::parse(o.stalls);

  std::cerr << "scw sim: " << o.config << ", " << width << " x " << height << ", P = " << P << ", "
            << o.frames << " frames, engine " << engine_name(o) << "\n";
  sim::PipelineChain<Build, Rtl> chain(setup, engines_of(o, built),
                                       host::pipeline::frames_beats<P>(ls),
                                       host::pipeline::frames_beats<P>(rs), pattern, pattern);
  const std::int64_t per_frame = static_cast<std::int64_t>(width) * height / P;
  chain.run(static_cast<std::size_t>(o.frames), (o.frames + 2) * per_frame * 8,
            [&](std::int64_t c, std::size_t done) {
              std::cerr << "\r  cycle " << c << ", " << done << " of " << o.frames << " results"
                        << std::flush;
            });
  std::cerr << "\r  " << chain.cycles() << " cycles, " << o.frames << " results            \n";
  const auto t = chain.timing();

  std::cout << std::fixed << std::setprecision(3);
  std::cout << "\n" << o.config << " configuration, " << width << " x " << height << ", window "
            << Build::kWindow << ", disparities " << so.dmin << " .. " << so.dmin + so.num_disp - 1
            << " (" << disparity::mode_name(so.mode) << " mode), P = " << P << ", engine "
            << engine_name(o) << ", " << kClockMhz << " MHz\n\n";
  std::cout << std::left << std::setw(24) << "" << std::right << std::setw(12) << "cycles"
            << std::setw(10) << "ms" << " | thesis: " << std::setw(7) << "FPGA" << std::setw(7)
            << "GPU" << std::setw(7) << "CPU" << "  (ms, Table 5.7)\n";
  nlohmann::json stages = nlohmann::json::array();
  for (const auto& s : t.stages) {
    stages.push_back({{"name", s.name}, {"busy_cycles", s.busy()}, {"busy_ms", ms(s.busy())},
                      {"first_in_cycle", s.first_in}, {"last_out_cycle", s.last_out}});
  }
  for (const ThesisRow& row : kThesis) {
    std::int64_t busy = 0;
    for (const auto& s : t.stages)
      if (s.name == row.block) busy = s.busy();
    std::cout << std::left << std::setw(24) << row.name << std::right << std::setw(12) << busy
              << std::setw(10) << ms(busy) << " | " << std::setw(15) << row.fpga << std::setw(7)
              << row.gpu << std::setw(7) << row.cpu << "\n";
  }
  const auto line = [&](const char* name, std::int64_t c, const double thesis[3]) {
    std::cout << std::left << std::setw(24) << name << std::right << std::setw(12) << c
              << std::setw(10) << ms(c) << " | ";
    if (thesis)
      std::cout << std::setw(15) << thesis[2] << std::setw(7) << thesis[1] << std::setw(7)
                << thesis[0];
    std::cout << "\n";
  };
  line("frame period T_P", t.period, kThesisPeriod);
  line("latency T_L, first beat", t.latency_first, kThesisLatency);
  line("latency T_L, last beat", t.latency_last, nullptr);
  nlohmann::json at_fmax;
  if (slow) {
    const auto ms_at = [&](std::int64_t c) { return c / (slow->fmax_mhz * 1000.0); };
    std::cout << "\nat the estimated Fmax of the slowest module, " << slow->module << " ("
              << slow->sta_ps << " ps of logic, " << std::setprecision(1) << slow->fmax_mhz
              << " MHz, docs/timing.md):" << std::setprecision(3) << " T_P " << ms_at(t.period)
              << " ms, T_L " << ms_at(t.latency_first) << " ms (thesis FPGA: "
              << kThesisPeriod[2] << " / " << kThesisLatency[2] << " ms at 125 MHz)\n";
    at_fmax = {{"module", slow->module},
               {"sta_ps", slow->sta_ps},
               {"fmax_mhz_est", slow->fmax_mhz},
               {"period_ms", ms_at(t.period)},
               {"latency_first_ms", ms_at(t.latency_first)},
               {"latency_last_ms", ms_at(t.latency_last)}};
  }
  std::cout << "\nbusy = a block's first beat in to its last beat out, last frame; T_P = "
               "between the last two results; T_L = the last frame's.\n"
            << "every block, per frame (cycles from the first input beat):\n";
  const auto report = chain.report();
  for (const auto& s : t.stages)
    std::cout << "  " << std::left << std::setw(16) << s.name << std::right << std::setw(10)
              << s.first_in << " .. " << std::setw(10) << s.last_out << "\n";
  std::cout << "FIFOs (depth, most held):";
  nlohmann::json fifos = nlohmann::json::array();
  for (const auto& f : report.fifos) {
    std::cout << " " << f.name << " " << f.depth << "/" << f.max_occupancy;
    fifos.push_back({{"name", f.name}, {"depth", f.depth}, {"max_occupancy", f.max_occupancy},
                     {"beats", f.beats}});
  }
  std::cout << "\n";
  nlohmann::json frames = nlohmann::json::array();
  for (std::size_t k = 0; k < t.frames.size(); ++k) {
    const auto& f = t.frames[k];
    const auto& res = chain.results()[k].data;
    nlohmann::json rj = app::result_json(res.frame);
    rj["input_error_left"] = res.input_error_left;
    rj["input_error_right"] = res.input_error_right;
    frames.push_back({{"first_in_cycle", f.first_in}, {"last_in_cycle", f.last_in},
                      {"result_cycle", f.result}, {"result", rj}});
    std::cout << "frame " << k << ": in " << f.first_in << " .. " << f.last_in << ", result "
              << f.result << ": " << app::severity_name(res.frame.severity) << ", "
              << res.frame.objects << " objects"
              << (res.frame.index != 0xffff
                      ? ", deciding at " + std::to_string(res.frame.distance_mm / 1000.0) + " m"
                      : std::string())
              << "\n";
  }
  nlohmann::json ref_json;
  if (o.reference) {
    std::cerr << "the floating-point chain (direct SAD reference or cv::StereoBM, flood fill, "
                 "Eigen) on the same pair...\n";
    const auto ref = host::pipeline::reference_frame(l, r, Build::kWindow, so, o.frames);
    const auto& got = chain.results().back().data.frame;
    const bool any = ref.result.index >= 0;
    const double ref_d = any ? ref.result.deciding.distance_m : 0.0;
    // The stage lists objects by root node, the reference by first pixel: the deciding object is
    // matched by its closest point and box, not by its place in the table.
    const auto* dec = any ? &ref.objects[static_cast<std::size_t>(ref.result.index)] : nullptr;
    const bool same_object =
        any ? got.index != 0xffff && got.closest_x == dec->closest_x &&
                  got.closest_y == dec->closest_y && got.d_max == dec->d_max &&
                  got.x_min == dec->x_min && got.x_max == dec->x_max && got.y_min == dec->y_min &&
                  got.y_max == dec->y_max
            : got.index == 0xffff;
    const bool agree = static_cast<int>(got.severity) == static_cast<int>(ref.result.severity) &&
                       got.objects == ref.result.objects && same_object &&
                       (!any || std::abs(got.distance_mm / 1000.0 - ref_d) <
                                    host::warning::distance_tolerance_m(
                                        ref.result.deciding,
                                        host::pipeline::warning_setup(l.cols, l.rows, so)));
    std::cout << "floating-point chain: " << app::severity_name(ref.result.severity) << ", "
              << ref.result.objects << " objects"
              << (any ? ", deciding object at " + std::to_string(ref_d) + " m" : std::string())
              << (agree ? ": agrees with the pipeline's last result (distance within 1 cm and "
                          "one code)\n"
                        : ": DIFFERS from the pipeline's last result\n");
    ref_json = {{"severity", app::severity_name(ref.result.severity)},
                {"objects", ref.result.objects},
                {"index", ref.result.index},
                {"distance_m", ref_d},
                {"agrees", agree}};
  }
  if (!o.json.empty()) {
    nlohmann::json j = {{"config", o.config},
                        {"width", width},
                        {"height", height},
                        {"window", Build::kWindow},
                        {"dmin", so.dmin},
                        {"num_disp", so.num_disp},
                        {"mode", disparity::mode_name(so.mode)},
                        {"clock_mhz", kClockMhz},
                        {"ppc", P},
                        {"engine", engine_name(o)},
                        {"stalls", o.stalls},
                        {"frames", o.frames},
                        {"cycles", chain.cycles()},
                        {"period_cycles", t.period},
                        {"period_ms", ms(t.period)},
                        {"latency_first_cycles", t.latency_first},
                        {"latency_first_ms", ms(t.latency_first)},
                        {"latency_last_cycles", t.latency_last},
                        {"latency_last_ms", ms(t.latency_last)},
                        {"max_latency_first_cycles", t.max_latency_first},
                        {"stages", stages},
                        {"fifos", fifos},
                        {"per_frame", frames},
                        {"reference", ref_json},
                        {"at_fmax_est", at_fmax},
                        {"thesis_ms",
                         {{"fpga", {{"period", kThesisPeriod[2]}, {"latency", kThesisLatency[2]}}},
                          {"gpu", {{"period", kThesisPeriod[1]}, {"latency", kThesisLatency[1]}}},
                          {"cpu",
                           {{"period", kThesisPeriod[0]}, {"latency", kThesisLatency[0]}}}}}};
    std::ofstream(o.json) << j.dump(2) << "\n";
    std::cerr << "wrote " << o.json << "\n";
  }
  return 0;
}

template <int P>
int run_small(const Options& o) {
  using Build = hls::pipeline::SmallPipeline<P>;
  if constexpr (P <= 2) {
    // At P = 2 the small build verilates only the blocks that differ from P = 1 in more than
    // width (tests/pipeline compare its whole top); the rest run as C++ here.
    if (P == 2 && o.engine == "rtl")
      std::cerr << "small build, P = 2: Verilated labelling, warning and merge; "
                   "the other blocks run as C++ (docs/pipeline.md)\n";
    return run<Build, typename sim::small_build::Rtl<P>::type>(
        o, Build::kMaxWidthPx, Build::kMaxHeight, 0, 16, sim::small_build::rtl_engines<P>());
  } else {
    return run<Build, sim::NoRtl>(o, Build::kMaxWidthPx, Build::kMaxHeight, 0, 16);
  }
}

template <int P>
int run_thesis(const Options& o) {
  using Build = hls::pipeline::ThesisPipeline<P>;
#if SCW_THESIS_RTL
  if constexpr (P == 1) return run<Build, sim::thesis_build::Rtl<1>::type>(o, 1280, 480, 20, 45);
#if SCW_THESIS_RTL_P2
  if constexpr (P == 2) return run<Build, sim::thesis_build::Rtl<2>::type>(o, 1280, 480, 20, 45);
#endif
#if SCW_THESIS_RTL_P4
  if constexpr (P == 4) return run<Build, sim::thesis_build::Rtl<4>::type>(o, 1280, 480, 20, 45);
#endif
#endif
  return run<Build, sim::NoRtl>(o, 1280, 480, 20, 45);
}

int run_sim(const Options& o) {
  if (o.frames < 1) throw std::invalid_argument("--frames must be at least 1");
  if (o.ppc != 1 && o.ppc != 2 && o.ppc != 4)
    throw std::invalid_argument("--ppc " + std::to_string(o.ppc) + ": use 1, 2 or 4");
  if (o.config == "small") {
    return o.ppc == 1 ? run_small<1>(o) : o.ppc == 2 ? run_small<2>(o) : run_small<4>(o);
  }
  if (o.config == "thesis") {
    return o.ppc == 1 ? run_thesis<1>(o) : o.ppc == 2 ? run_thesis<2>(o) : run_thesis<4>(o);
  }
  throw std::invalid_argument("--config " + o.config +
                              ": use thesis (1280 x 480, window 21, disparities 20 .. 64) or "
                              "small (128 x 96, window 9, 0 .. 15)");
}

}  // namespace

void add_sim_command(CLI::App& app) {
  auto o = std::make_shared<Options>();
  auto* cmd = app.add_subcommand(
      "sim", "Clock the whole pipeline (frames back to back): busy time per stage, frame period "
             "and latency beside the thesis's Table 5.7 (docs/performance.md)");
  cmd->add_option("--config", o->config, "thesis or small")->capture_default_str();
  cmd->add_option("--ppc", o->ppc, "pixels per beat: 1, 2 or 4")->capture_default_str();
  cmd->add_option("--frames", o->frames, "frames back to back")->capture_default_str();
  cmd->add_option("--engine", o->engine,
                  "cpp: every block's C++ model; rtl: every block Verilated (thesis size: "
                  "build with -DSCW_THESIS_RTL=ON)")
      ->capture_default_str();
  cmd->add_option("--rtl-stages", o->rtl_stages,
                  "with --engine cpp: these blocks Verilated, e.g. labelling,warning");
  cmd->add_option("--left", o->left, "left image (default: a synthetic street scene)");
  cmd->add_option("--right", o->right, "right image");
  cmd->add_option("--mode", o->mode, "disparity mode: thesis or opencv")->capture_default_str();
  cmd->add_option("--min-disp", o->dmin, "smallest disparity (default: the configuration's)");
  cmd->add_option("--num-disp", o->num_disp, "candidates (default: the configuration's)");
  cmd->add_option("--stalls", o->stalls,
                  "input gaps and output backpressure: none, idle, backpressure, both, random:SEED")
      ->capture_default_str();
  cmd->add_option("--json", o->json, "write the measurements as JSON");
  cmd->add_option("--synth-json", o->synth_json,
                  "a `scw synth --json` report of the same --config and --ppc: also give T_P and "
                  "T_L in ms at the estimated Fmax of its slowest module");
  cmd->add_flag("--reference", o->reference,
                "also run the floating-point chain on the pair and compare the frame result");
  cmd->callback([o] {
    try {
      const int rc = run_sim(*o);
      if (rc != 0) throw CLI::RuntimeError(rc);
    } catch (const std::invalid_argument& e) {
      std::cerr << "scw sim: " << e.what() << "\n";
      throw CLI::RuntimeError(2);
    }
  });
}

}  // namespace scw::cli
