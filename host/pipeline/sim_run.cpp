// SPDX-License-Identifier: Apache-2.0
// run_sim() and sim_json() (host/pipeline/sim_run.hpp).
#include "host/pipeline/sim_run.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

#include "hls/pipeline/pipeline_params.hpp"
#include "host/app/run.hpp"
#include "host/io/image_file.hpp"
#include "host/pipeline/reference_chain.hpp"
#include "host/pipeline/setup.hpp"
#include "host/pipeline/synthetic.hpp"
#include "host/pipeline/thesis_figures.hpp"
#include "host/warning/reference.hpp"
#include "sim/builds/pipeline_small_rtl.hpp"
#include "sim/pipeline/pipeline_chain.hpp"
#if SCW_THESIS_RTL
#include "sim/builds/pipeline_thesis_rtl.hpp"
#endif

namespace scw::host::pipeline {
namespace {

/// `built`: the blocks the build has as Verilated models (--engine rtl takes those).
sim::PipelineEngines engines_of(const SimOptions& o, const sim::PipelineEngines& built) {
  if (o.engine == "cpp" && o.rtl_stages.empty()) return sim::PipelineEngines::all(sim::Engine::cpp);
  if (o.engine == "rtl") return built;
  if (o.engine != "cpp")
    throw std::invalid_argument("--engine " + o.engine +
                                ": use cpp, rtl or rtl-top (and --rtl-stages with cpp)");
  auto e = sim::PipelineEngines::all(sim::Engine::cpp);
  for (const std::string& b : o.rtl_stages) {
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

std::string engine_name(const SimOptions& o) {
  std::string rtl;
  for (const std::string& b : o.rtl_stages) rtl += (rtl.empty() ? "" : ",") + b;
  return rtl.empty() ? o.engine : "mixed (rtl: " + rtl + ")";
}

/// The pair to stream: the user's (converted to grey and resized to the frame) or a synthetic
/// street at the configuration's disparity range.
std::pair<cv::Mat, cv::Mat> input_pair(const SimOptions& o, int w, int h, int dmin, int dmax,
                                       std::ostream& log) {
  if (o.left.empty() != o.right.empty())
    throw std::invalid_argument("give both --left and --right, or neither (synthetic scene)");
  if (o.left.empty()) {
    const auto p = synthetic_pair(w, h, dmin + 2, street_boxes(w, h, dmin, dmax), 7);
    return {p.left, p.right};
  }
  cv::Mat l = io::read_grey_image(o.left), r = io::read_grey_image(o.right);
  if (l.size() != r.size()) throw std::invalid_argument("--left and --right differ in size");
  if (l.cols != w || l.rows != h) {
    log << "resizing the pair from " << l.cols << " x " << l.rows << " to the " << o.config
        << " frame, " << w << " x " << h << "\n";
    cv::resize(l, l, cv::Size(w, h), 0, 0, cv::INTER_AREA);
    cv::resize(r, r, cv::Size(w, h), 0, 0, cv::INTER_AREA);
  }
  return {l, r};
}

/// The floating-point chain on the pair beside the pipeline's last result. The stage lists
/// objects by root node, the reference by first pixel: the deciding object is matched by its
/// closest point and box, not by its place in the table.
ReferenceCheck check_reference(const cv::Mat& l, const cv::Mat& r, int window,
                               const StageOptions& so, int frames,
                               const hls::warning::FrameResult& got) {
  const auto ref = reference_frame(l, r, window, so, frames);
  ReferenceCheck c;
  c.severity = ref.result.severity;
  c.objects = ref.result.objects;
  c.index = ref.result.index;
  const bool any = ref.result.index >= 0;
  c.distance_m = any ? ref.result.deciding.distance_m : 0.0;
  const auto* dec = any ? &ref.objects[static_cast<std::size_t>(ref.result.index)] : nullptr;
  const bool same_object =
      any ? got.index != 0xffff && got.closest_x == dec->closest_x &&
                got.closest_y == dec->closest_y && got.d_max == dec->d_max &&
                got.x_min == dec->x_min && got.x_max == dec->x_max && got.y_min == dec->y_min &&
                got.y_max == dec->y_max
          : got.index == 0xffff;
  c.agrees = got.severity == ref.result.severity && got.objects == ref.result.objects &&
             same_object &&
             (!any || std::abs(got.distance_mm / 1000.0 - c.distance_m) <
                          warning::distance_tolerance_m(ref.result.deciding,
                                                        warning_setup(l.cols, l.rows, so)));
  return c;
}

/// What every engine's run starts from: the report's fixed fields, the pair and the setup.
struct Prepared {
  SimRun s;
  StageOptions so;
  cv::Mat left, right;
  sim::PipelineSetup setup;
  sim::StallPattern pattern;
  std::int64_t max_cycles = 0;
};

template <typename Build>
Prepared prepare(const SimOptions& o, std::ostream& log, int width, int height, int dmin_default,
                 int num_disp_default) {
  constexpr int P = Build::kPpc;
  Prepared p;
  SimRun& s = p.s;
  s.options = o;
  s.engine = engine_name(o);
  s.width = width;
  s.height = height;
  s.window = Build::kWindow;
  s.ppc = P;
  // Read before the run, so a wrong report fails in a second, not after minutes of simulation.
  if (!o.synth_json.empty()) s.slowest = synth::slowest_module(o.synth_json, o.config, P);
  StageOptions& so = p.so;
  so.mode = disparity::mode_from_name(o.mode);
  so.edge_candidates = o.edge_candidates;
  so.dmin = o.dmin >= 0 ? o.dmin : dmin_default;
  so.num_disp = o.num_disp > 0 ? o.num_disp : num_disp_default;
  so.tiles_x = Build::kMaxTilesX;
  so.tiles_y = Build::kMaxTilesY;
  so.min_area = std::max(20, width * height / 2000);
  s.mode = so.mode;
  s.dmin = so.dmin;
  s.num_disp = so.num_disp;
  std::tie(p.left, p.right) = input_pair(o, width, height, so.dmin, so.dmin + so.num_disp - 1, log);
  const auto knots = identity_knots(width, height, Build::kGridLog2);
  p.setup = make_setup(width, height, Build::kGridLog2, so, knots, knots, 1);
  p.pattern = sim::StallPattern::parse(o.stalls);
  const std::int64_t per_frame = static_cast<std::int64_t>(width) * height / P;
  p.max_cycles = (o.frames + 2) * per_frame * 8;
  log << "scw sim: " << o.config << ", " << width << " x " << height << ", P = " << P << ", "
      << o.frames << " frames, engine " << s.engine << "\n";
  return p;
}

/// The progress line a run rewrites as it goes (the chain and the top call it alike).
void progress(std::ostream& log, std::int64_t c, std::size_t done, int frames) {
  log << "\r  cycle " << c << ", " << done << " of " << frames << " results" << std::flush;
}

template <typename Build>
void finish(Prepared& p, const SimOptions& o, std::ostream& log) {
  log << "\r  " << p.s.cycles << " cycles, " << o.frames << " results            \n";
  if (o.reference) {
    log << "the floating-point chain (direct SAD reference or cv::StereoBM, flood fill, Eigen) "
           "on the same pair...\n";
    p.s.reference =
        check_reference(p.left, p.right, Build::kWindow, p.so, o.frames, p.s.results.back().frame);
  }
}

template <int P>
auto frames_of(const cv::Mat& m, int frames) {
  return frames_beats<P>(std::vector<cv::Mat>(static_cast<std::size_t>(frames), m));
}

template <typename Build, typename Rtl>
SimRun run(const SimOptions& o, std::ostream& log, int width, int height, int dmin_default,
           int num_disp_default,
           const sim::PipelineEngines& built = sim::PipelineEngines::all(sim::Engine::rtl)) {
  constexpr int P = Build::kPpc;
  Prepared p = prepare<Build>(o, log, width, height, dmin_default, num_disp_default);
  sim::PipelineChain<Build, Rtl> chain(
      p.setup, engines_of(o, built), frames_of<P>(p.left, o.frames),
      frames_of<P>(p.right, o.frames), p.pattern, p.pattern, o.threads);
  chain.run(static_cast<std::size_t>(o.frames), p.max_cycles,
            [&](std::int64_t c, std::size_t done) { progress(log, c, done, o.frames); });
  p.s.cycles = chain.cycles();
  p.s.timing = chain.timing();
  p.s.report = chain.report();
  for (const auto& res : chain.results()) p.s.results.push_back(res.data);
  finish<Build>(p, o, log);
  return std::move(p.s);
}

/// `--engine rtl-top`: the scw_pipeline top Verilated as one model. It agrees with the chain
/// clock for clock at its ports (tests/pipeline), so the results and every frame's input and
/// result cycles are the chain's; the blocks' busy spans and the FIFOs inside it are not seen.
template <typename Build, typename Top>
SimRun run_top(const SimOptions& o, std::ostream& log, int width, int height, int dmin_default,
               int num_disp_default) {
  constexpr int P = Build::kPpc;
  Prepared p = prepare<Build>(o, log, width, height, dmin_default, num_disp_default);
  Top top(p.setup);
  sim::TopRunControl ctl;
  ctl.progress = [&](std::int64_t c, std::size_t done) { progress(log, c, done, o.frames); };
  const auto t =
      top.run(frames_of<P>(p.left, o.frames), frames_of<P>(p.right, o.frames),
              static_cast<std::size_t>(o.frames), p.max_cycles, p.pattern, p.pattern, ctl);
  if (top.errors() != 0)
    throw std::runtime_error("scw_pipeline raised its error bits (" + std::to_string(top.errors()) +
                             ")");
  p.s.cycles = t.cycles;
  p.s.timing = sim::top_timing(t);
  for (const auto& res : t.results) p.s.results.push_back(res.data);
  finish<Build>(p, o, log);
  return std::move(p.s);
}

/// `--engine rtl-top` where the build has no such top: what to build instead.
[[noreturn]] void no_top(const SimOptions& o) {
  throw std::invalid_argument(
      "--engine rtl-top: this scw has no Verilated scw_pipeline top for --config " + o.config +
      " at --ppc " + std::to_string(o.ppc) +
      (o.config == "thesis" ? " (configure with -DSCW_THESIS_RTL=ON and the width in "
                              "-DSCW_THESIS_RTL_PPC)"
                            : " (the small build has P = 1 and 2)"));
}

template <int P>
SimRun run_small(const SimOptions& o, std::ostream& log) {
  using Build = hls::pipeline::SmallPipeline<P>;
  if (o.engine == "rtl-top") {
    if constexpr (P <= 2)
      return run_top<Build, sim::small_build::Top<P>>(o, log, Build::kMaxWidthPx, Build::kMaxHeight,
                                                      0, Build::kNumDisp);
    no_top(o);
  }
  if constexpr (P <= 2) {
    // At P = 2 the small build verilates only the blocks that differ from P = 1 in more than
    // width (tests/pipeline compare its whole top); the rest run as C++ here.
    if (P == 2 && o.engine == "rtl")
      log << "small build, P = 2: Verilated labelling, warning and merge; the other blocks run "
             "as C++ (docs/pipeline.md)\n";
    return run<Build, typename sim::small_build::Rtl<P>::type>(
        o, log, Build::kMaxWidthPx, Build::kMaxHeight, 0, Build::kNumDisp, sim::small_build::rtl_engines<P>());
  } else {
    return run<Build, sim::NoRtl>(o, log, Build::kMaxWidthPx, Build::kMaxHeight, 0, Build::kNumDisp);
  }
}

template <int P>
SimRun run_thesis(const SimOptions& o, std::ostream& log) {
  using Build = hls::pipeline::ThesisPipeline<P>;
  constexpr int w = Build::kMaxWidthPx, h = Build::kMaxHeight;
  constexpr int kMinDisp = 20;  // the thesis's range: 45 candidates from 20 px
#if SCW_THESIS_RTL
  if constexpr (sim::thesis_build::kBuilt<P>) {
    if (o.engine == "rtl-top")
      return run_top<Build, sim::thesis_build::Top<P>>(o, log, w, h, kMinDisp, Build::kNumDisp);
    return run<Build, typename sim::thesis_build::Rtl<P>::type>(o, log, w, h, kMinDisp,
                                                                Build::kNumDisp);
  }
#endif
  if (o.engine == "rtl-top") no_top(o);
  return run<Build, sim::NoRtl>(o, log, w, h, kMinDisp, Build::kNumDisp);
}

}  // namespace

SimRun run_sim(const SimOptions& o, std::ostream& log) {
  if (o.frames < 1) throw std::invalid_argument("--frames must be at least 1");
  if (o.ppc != 1 && o.ppc != 2 && o.ppc != 4)
    throw std::invalid_argument("--ppc " + std::to_string(o.ppc) + ": use 1, 2 or 4");
  sim::check_threads(o.threads, "--threads");
  if (o.threads != 1 && o.engine == "rtl-top")
    throw std::invalid_argument(
        "--threads 2 splits the chain of blocks over two threads; the rtl-top engine is one "
        "Verilated model on one thread: use --engine rtl, or --threads 1");
  if (o.engine != "cpp" && !o.rtl_stages.empty())
    throw std::invalid_argument("--rtl-stages picks blocks of --engine cpp; --engine " + o.engine +
                                " already Verilates every block: give one of the two");
  // An unknown engine or block is named before anything is set up or printed.
  if (o.engine != "rtl-top") engines_of(o, sim::PipelineEngines::all(sim::Engine::rtl));
  if (o.config == "small")
    return o.ppc == 1 ? run_small<1>(o, log) : o.ppc == 2 ? run_small<2>(o, log)
                                                          : run_small<4>(o, log);
  if (o.config == "thesis")
    return o.ppc == 1 ? run_thesis<1>(o, log) : o.ppc == 2 ? run_thesis<2>(o, log)
                                                           : run_thesis<4>(o, log);
  throw std::invalid_argument("--config " + o.config +
                              ": use thesis (1280 x 480, window 21, disparities 20 .. 64) or "
                              "small (128 x 96, window 9, 0 .. 15)");
}

nlohmann::json sim_json(const SimRun& r) {
  using thesis::ms;
  const sim::PipelineTiming& t = r.timing;
  nlohmann::json stages = nlohmann::json::array();
  for (const auto& s : t.stages)
    stages.push_back({{"name", s.name}, {"busy_cycles", s.busy()}, {"busy_ms", ms(s.busy())},
                      {"first_in_cycle", s.first_in}, {"last_out_cycle", s.last_out}});
  nlohmann::json fifos = nlohmann::json::array();
  for (const auto& f : r.report.fifos)
    fifos.push_back({{"name", f.name}, {"depth", f.depth}, {"max_occupancy", f.max_occupancy},
                     {"beats", f.beats}});
  nlohmann::json frames = nlohmann::json::array();
  for (std::size_t k = 0; k < t.frames.size(); ++k) {
    const auto& f = t.frames[k];
    const auto& res = r.results[k];
    nlohmann::json rj = app::result_json(res.frame);
    rj["input_error_left"] = res.input_error_left;
    rj["input_error_right"] = res.input_error_right;
    frames.push_back({{"first_in_cycle", f.first_in}, {"last_in_cycle", f.last_in},
                      {"result_cycle", f.result}, {"result", rj}});
  }
  nlohmann::json ref;
  if (r.reference)
    ref = {{"severity", app::severity_name(r.reference->severity)},
           {"objects", r.reference->objects},
           {"index", r.reference->index},
           {"distance_m", r.reference->distance_m},
           {"agrees", r.reference->agrees}};
  nlohmann::json at_fmax;
  if (r.slowest) {
    const auto ms_at = [&](std::int64_t c) { return c / (r.slowest->fmax_mhz * 1000.0); };
    at_fmax = {{"module", r.slowest->module},
               {"sta_ps", r.slowest->sta_ps},
               {"fmax_mhz_est", r.slowest->fmax_mhz},
               {"period_ms", ms_at(t.period)},
               {"latency_first_ms", ms_at(t.latency_first)},
               {"latency_last_ms", ms_at(t.latency_last)}};
  }
  const SimOptions& o = r.options;
  return {{"config", o.config},
          {"width", r.width},
          {"height", r.height},
          {"window", r.window},
          {"dmin", r.dmin},
          {"num_disp", r.num_disp},
          {"mode", disparity::mode_name(r.mode)},
          {"edge_candidates", o.edge_candidates},
          {"clock_mhz", thesis::kClockMhz},
          {"ppc", r.ppc},
          {"engine", r.engine},
          {"stalls", o.stalls},
          {"frames", o.frames},
          {"threads", o.threads},
          {"cycles", r.cycles},
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
          {"reference", ref},
          {"at_fmax_est", at_fmax},
          {"thesis_ms",
           {{"fpga", {{"period", thesis::kPeriodMs.fpga}, {"latency", thesis::kLatencyMs.fpga}}},
            {"gpu", {{"period", thesis::kPeriodMs.gpu}, {"latency", thesis::kLatencyMs.gpu}}},
            {"cpu", {{"period", thesis::kPeriodMs.cpu}, {"latency", thesis::kLatencyMs.cpu}}}}}};
}

std::string ReferenceCheck::text() const {
  std::ostringstream s;
  s << "floating-point chain: " << hls::warning::severity_name(severity) << ", " << objects
    << " objects";
  if (index >= 0) s << ", deciding object at " << std::to_string(distance_m) << " m";
  s << (agrees ? ": agrees with the pipeline's last result (distance within 1 cm and one code)"
               : ": DIFFERS from the pipeline's last result");
  return s.str();
}

}  // namespace scw::host::pipeline
