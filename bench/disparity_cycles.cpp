// SPDX-License-Identifier: Apache-2.0
// Measured cycles of the disparity stage at the thesis size (1280 x 480, N = 21, d = 20 .. 64,
// P = 1 and 2, thesis and opencv mode): the Verilated scw_disparity and its C++ model, each
// driven alone by a plain loop with frames back to back.
//
// The loop offers both inputs every cycle while beats remain and always takes the output, and
// keeps only the cycle each input beat was accepted and each output beat was taken: a full-size
// run is millions of cycles, too many for sim::run_join's per-cycle trace. From those cycles it
// prints per P, mode and engine the frame period, the latency, total cycles, ms at 125 MHz and
// the simulation speed, compares them with the thesis FPGA (Leu, Table 5.7), checks every
// output pixel against the direct reference (unless --no-reference) and, with --engine both,
// requires RTL and C++ to agree on every output beat and every cycle.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <opencv2/imgproc.hpp>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench/cycle_bench_options.hpp"
#include "bench/disparity_bench_configs.hpp"
#include "hls/disparity/disparity.hpp"
#include "host/disparity/run_model.hpp"
#include "host/io/image_file.hpp"
#include "host/pipeline/thesis_figures.hpp"
#include "host/reference/disparity_ref.hpp"
#include "sim/core/frame_beats.hpp"
#include "sim/models/disparity_model.hpp"
#include "sim/rtl/disparity_rtl.hpp"
#include "sim/rtl/rtl_params.hpp"
#include "Vbench_disparity_p1.h"
#include "Vbench_disparity_p1_scw_disparity.h"
#include "Vbench_disparity_p2.h"
#include "Vbench_disparity_p2_scw_disparity.h"

namespace {

using namespace scw;
using host::io::format_number;
using hls::disparity::DisparityConfig;
using nlohmann::json;

constexpr int W = bench::kDispBenchWidth;
constexpr int H = bench::kDispBenchHeight;
constexpr double kClockMhz = host::pipeline::thesis::kClockMhz;

// The thesis FPGA at 125 MHz (Leu, Table 5.7): what the measured figures are set against.
constexpr double kThesisPeriodMs = host::pipeline::thesis::kPeriodMs.fpga;
constexpr double kThesisLatencyMs = host::pipeline::thesis::kLatencyMs.fpga;

template <int P>
using Kernel = hls::disparity::Disparity<bench::DisparityBench<P>>;

// bench/CMakeLists.txt passes the same values to Verilator with -G; the RTL's own latency and
// queue must also be the model's, or "same cycles" below could not hold.
static_assert(sim::disparity_params_match<Vbench_disparity_p1_scw_disparity, Kernel<1>>());
static_assert(sim::disparity_params_match<Vbench_disparity_p2_scw_disparity, Kernel<2>>());

template <int P>
using RtlModel = std::conditional_t<P == 1, Vbench_disparity_p1, Vbench_disparity_p2>;

struct Options {
  std::string left = SCW_DATA_DIR "/tsukuba/scene1.row3.col3.ppm";
  std::string right = SCW_DATA_DIR "/tsukuba/scene1.row3.col4.ppm";
  std::vector<int> ppc{1, 2};
  std::string engine = "both";
  std::string mode = "both";
  int frames = 3;
  bool reference = true;
  std::string json_out;
};

/// One frame pair at the bench size.
struct Pair {
  cv::Mat left, right;
};

/// Frame k turned by 8 k columns (circularly), so that successive frames differ.
cv::Mat shifted(const cv::Mat& big, int k) {
  const int sh = (8 * k) % W;
  cv::Mat f(big.size(), CV_8UC1);
  if (sh == 0) {
    big.copyTo(f);
  } else {
    big.colRange(W - sh, W).copyTo(f.colRange(0, sh));
    big.colRange(0, W - sh).copyTo(f.colRange(sh, W));
  }
  return f;
}

std::vector<Pair> bench_frames(const Options& o, cv::Size& native) {
  // The CLI's reader (cv::IMREAD_GRAYSCALE), so the pictures are the ones `scw disparity` would
  // see.
  const cv::Mat l = host::io::read_grey_image(o.left);
  const cv::Mat r = host::io::read_grey_image(o.right);
  if (l.size() != r.size()) throw std::runtime_error("the left and right images differ in size");
  native = l.size();
  cv::Mat bl, br;
  cv::resize(l, bl, cv::Size(W, H), 0, 0, cv::INTER_LINEAR);
  cv::resize(r, br, cv::Size(W, H), 0, 0, cv::INTER_LINEAR);
  std::vector<Pair> v;
  for (int k = 0; k < o.frames; ++k) v.push_back({shifted(bl, k), shifted(br, k)});
  return v;
}

/// What one run recorded: every beat's cycle, no per-cycle trace.
template <typename Out>
struct Run {
  std::string engine;
  std::vector<std::int64_t> in_cycle;   // input beat i (left and right together) accepted
  std::vector<std::int64_t> out_cycle;  // output beat i taken
  std::vector<Out> out;
  std::int64_t total_cycles = 0;  // cycles until the last output beat was taken, inclusive
  bool err = false;
  bool lockstep = true;  // left and right accepted in the same cycles (the stage's contract)
  double cpu_s = 0;      // process CPU time: the speed figure on a shared machine
  double wall_s = 0;
};

/// Drives `model` with both inputs valid while beats remain and the output always ready.
template <typename Model, typename ErrFn>
Run<typename Model::out_type> drive(const std::string& label, const std::string& engine,
                                    Model& model, const std::vector<typename Model::a_type>& left,
                                    const std::vector<typename Model::b_type>& right,
                                    std::size_t beats_per_frame, ErrFn err_of) {
  using Out = typename Model::out_type;
  Run<Out> r;
  r.engine = engine;
  const std::size_t n = left.size();
  r.in_cycle.assign(n, -1);
  r.out_cycle.reserve(n);
  r.out.reserve(n);
  std::size_t il = 0, ir = 0;
  // A stage that stops is a bug; the stage needs about one cycle per beat plus a few rows.
  const std::int64_t limit = 2 * static_cast<std::int64_t>(n) + 100'000;
  const std::clock_t c0 = std::clock();
  const auto t0 = std::chrono::steady_clock::now();
  auto last_print = t0;
  std::int64_t c = 0;
  for (; r.out.size() < n; ++c) {
    if (c > limit)
      throw std::logic_error(label + ": the stage stopped (" + std::to_string(r.out.size()) +
                             " of " + std::to_string(n) + " output beats after " +
                             std::to_string(c) + " cycles)");
    const bool lv = il < n, rv = ir < n;
    const auto o = model.eval(lv, left[lv ? il : 0], rv, right[rv ? ir : 0], true);
    const bool lt = lv && o.a_ready, rt = rv && o.b_ready;
    if (lt != rt) r.lockstep = false;
    if (lt) r.in_cycle[il++] = c;
    if (rt) ++ir;
    if (o.out_valid) {
      r.out.push_back(o.out);
      r.out_cycle.push_back(c);
    }
    model.tick();
    if ((c & 0xffff) == 0) {
      const auto now = std::chrono::steady_clock::now();
      if (std::chrono::duration<double>(now - last_print).count() >= 5.0) {
        last_print = now;
        const double el = std::chrono::duration<double>(now - t0).count();
        std::fprintf(stderr, "  [%s] cycle %lld, %.2f frames out, %.3f Mcycles/s (wall)\n",
                     label.c_str(), static_cast<long long>(c),
                     static_cast<double>(r.out.size()) / static_cast<double>(beats_per_frame),
                     static_cast<double>(c) / el / 1e6);
      }
    }
  }
  r.total_cycles = c;
  r.cpu_s = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
  r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.err = err_of(model);
  return r;
}

/// The figures of one run; also checks the output's framing (sof and eol where they belong).
template <typename Out>
json measure(const Run<Out>& r, int P, const std::string& mode, int frames, std::string& problem) {
  const std::int64_t bpr = W / P;
  const std::size_t bpf = static_cast<std::size_t>(bpr) * H;
  json j;
  j["ppc"] = P;
  j["mode"] = mode;
  j["engine"] = r.engine;
  j["frames"] = frames;
  j["ideal_cycles_per_frame"] = static_cast<std::int64_t>(bpf);
  j["total_cycles"] = r.total_cycles;
  j["total_ms_at_125mhz"] = static_cast<double>(r.total_cycles) / (kClockMhz * 1e3);
  j["cpu_s"] = r.cpu_s;
  j["wall_s"] = r.wall_s;
  j["sim_cycles_per_cpu_s"] = static_cast<double>(r.total_cycles) / r.cpu_s;
  j["err"] = r.err;
  j["lockstep"] = r.lockstep;

  std::size_t bad_framing = 0;
  for (std::size_t i = 0; i < r.out.size(); ++i)
    if (r.out[i].sof != (i % bpf == 0) ||
        r.out[i].eol != ((i + 1) % static_cast<std::size_t>(bpr) == 0))
      ++bad_framing;
  j["bad_framing_beats"] = bad_framing;
  if (bad_framing != 0 || r.err || !r.lockstep)
    problem = std::to_string(bad_framing) + " beats with a misplaced sof/eol, err=" +
              std::to_string(r.err) + ", left/right in step=" + std::to_string(r.lockstep);

  // Per frame: the input sof accepted, the output sof taken, the last output beat.
  json jf = json::array();
  std::vector<std::int64_t> in_sof, out_sof, out_last;
  for (int k = 0; k < frames; ++k) {
    const std::size_t b0 = static_cast<std::size_t>(k) * bpf;
    in_sof.push_back(r.in_cycle[b0]);
    out_sof.push_back(r.out_cycle[b0]);
    out_last.push_back(r.out_cycle[b0 + bpf - 1]);
    json x{{"in_sof", in_sof.back()},
           {"in_last", r.in_cycle[b0 + bpf - 1]},
           {"out_sof", out_sof.back()},
           {"out_last", out_last.back()},
           // The frame's whole stay: first pixel in to last result out.
           {"in_sof_to_out_last", out_last.back() - in_sof.back()}};
    if (k > 0) {
      x["out_period"] = out_sof[k] - out_sof[k - 1];
      x["in_period"] = in_sof[k] - in_sof[k - 1];
    }
    jf.push_back(x);
  }
  j["per_frame"] = jf;

  // Steady state: the last pair of frames. The pair (0, 1) is not: frame 0's top R rows are
  // the invalid code, which the reader emits from cycle 2 without waiting for results, so
  // frame 0's output sof is early by about the latency; from frame 1 on the output is one
  // continuous stream. So a steady period needs three frames.
  std::int64_t out_period = -1, in_period = -1;
  j["steady"] = frames >= 3;
  if (frames >= 2) {
    out_period = out_sof[frames - 1] - out_sof[frames - 2];
    in_period = in_sof[frames - 1] - in_sof[frames - 2];
  }
  j["cycles_per_frame"] = out_period;
  j["input_cycles_per_frame"] = in_period;
  j["equals_ideal"] = out_period == static_cast<std::int64_t>(bpf) &&
                      in_period == static_cast<std::int64_t>(bpf);
  j["ms_per_frame_at_125mhz"] = static_cast<double>(out_period) / (kClockMhz * 1e3);

  // Latency of beat i (output i taken - input i accepted), over the frames after the first
  // when there are any: in steady state it should be one number.
  const std::size_t from = frames >= 2 ? bpf : 0;
  std::int64_t lmin = INT64_MAX, lmax = INT64_MIN;
  for (std::size_t i = from; i < r.out_cycle.size(); ++i) {
    const std::int64_t l = r.out_cycle[i] - r.in_cycle[i];
    lmin = std::min(lmin, l);
    lmax = std::max(lmax, l);
  }
  j["latency_cycles_min"] = lmin;
  j["latency_cycles_max"] = lmax;
  j["latency_rows_min"] = static_cast<double>(lmin) / static_cast<double>(bpr);
  j["latency_rows_max"] = static_cast<double>(lmax) / static_cast<double>(bpr);
  j["latency_ms_at_125mhz"] = static_cast<double>(lmax) / (kClockMhz * 1e3);
  // The first frame: its output starts before its input's rows of results are in (the top R
  // rows are the invalid code), so the beat latency grows until the pipeline is full.
  std::int64_t f0min = INT64_MAX, f0max = INT64_MIN;
  for (std::size_t i = 0; i < bpf && i < r.out_cycle.size(); ++i) {
    const std::int64_t l = r.out_cycle[i] - r.in_cycle[i];
    f0min = std::min(f0min, l);
    f0max = std::max(f0max, l);
  }
  j["frame0_latency_cycles_min"] = f0min;
  j["frame0_latency_cycles_max"] = f0max;
  const std::int64_t stay = out_last.back() - in_sof.back();
  j["frame_in_to_out_cycles"] = stay;
  j["frame_in_to_out_ms_at_125mhz"] = static_cast<double>(stay) / (kClockMhz * 1e3);
  j["thesis_period_ms"] = kThesisPeriodMs;
  j["thesis_latency_ms"] = kThesisLatencyMs;
  if (out_period > 0)
    j["period_ratio_to_thesis"] =
        static_cast<double>(out_period) / (kClockMhz * 1e3) / kThesisPeriodMs;
  j["latency_ratio_to_thesis"] = static_cast<double>(lmax) / (kClockMhz * 1e3) / kThesisLatencyMs;
  j["frame_in_to_out_ratio_to_thesis_latency"] =
      static_cast<double>(stay) / (kClockMhz * 1e3) / kThesisLatencyMs;
  return j;
}

/// Empty when RTL and C++ agree on every beat and cycle, else the first difference.
template <typename Out>
std::string first_difference(const Run<Out>& a, const Run<Out>& b) {
  if (a.out.size() != b.out.size())
    return "output beat counts " + std::to_string(a.out.size()) + " vs " +
           std::to_string(b.out.size());
  for (std::size_t i = 0; i < a.in_cycle.size() && i < b.in_cycle.size(); ++i)
    if (a.in_cycle[i] != b.in_cycle[i])
      return "input beat " + std::to_string(i) + " accepted in cycle " +
             std::to_string(a.in_cycle[i]) + " (" + a.engine + ") vs " +
             std::to_string(b.in_cycle[i]) + " (" + b.engine + ")";
  for (std::size_t i = 0; i < a.out.size(); ++i) {
    if (a.out_cycle[i] != b.out_cycle[i])
      return "output beat " + std::to_string(i) + " taken in cycle " +
             std::to_string(a.out_cycle[i]) + " (" + a.engine + ") vs " +
             std::to_string(b.out_cycle[i]) + " (" + b.engine + ")";
    if (a.out[i] != b.out[i]) {
      std::ostringstream s;
      s << "output beat " << i << " (cycle " << a.out_cycle[i] << ") differs:";
      for (const auto* x : {&a, &b}) {
        s << " " << x->engine << " {";
        for (std::size_t k = 0; k < x->out[i].px.size(); ++k)
          s << (k ? " " : "") << x->out[i].px[k];
        s << " sof " << x->out[i].sof << " eol " << x->out[i].eol << "}";
      }
      return s.str();
    }
  }
  if (a.total_cycles != b.total_cycles)
    return "total cycles " + std::to_string(a.total_cycles) + " vs " +
           std::to_string(b.total_cycles);
  return {};
}

struct Row {
  json j;
};

/// The direct reference's output per mode and frame, shared by both P: the stage's result is
/// the same picture whatever the beat width, and the reference costs seconds per frame.
using RefCache = std::map<std::pair<std::string, int>, std::vector<std::uint16_t>>;

const std::vector<std::uint16_t>& reference_frame(RefCache& cache, const std::string& mode,
                                                  int k, const Pair& p,
                                                  const DisparityConfig& cfg) {
  auto it = cache.find({mode, k});
  if (it != cache.end()) return it->second;
  const auto t0 = std::chrono::steady_clock::now();
  auto v = reference::disparity_reference(p.left.ptr<std::uint8_t>(0), p.right.ptr<std::uint8_t>(0),
                                          W, H, bench::kDispBenchWindow,
                                          bench::kDispBenchNumDisp, cfg);
  std::fprintf(stderr, "  reference, %s mode, frame %d: %.1f s\n", mode.c_str(), k,
               std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  return cache.emplace(std::make_pair(mode, k), std::move(v)).first->second;
}

template <int P>
void bench_ppc(const Options& o, const std::vector<Pair>& pairs, const std::string& mode,
               RefCache& refs, std::vector<Row>& rows, bool& ok) {
  using Params = bench::DisparityBench<P>;
  using Pix = typename Params::pixel_beat;
  using Disp = typename Params::disp_beat;
  const std::size_t bpf = static_cast<std::size_t>(W / P) * H;
  const auto m = mode == "thesis" ? disparity::Mode::thesis : disparity::Mode::opencv;
  const DisparityConfig cfg = disparity::mode_config(m, W, H, bench::kDispBenchDMin);

  std::vector<Pix> left, right;
  for (const auto& p : pairs) {
    const auto l = sim::frame_beats<P>(p.left.ptr<std::uint8_t>(0), W, H);
    const auto r = sim::frame_beats<P>(p.right.ptr<std::uint8_t>(0), W, H);
    left.insert(left.end(), l.begin(), l.end());
    right.insert(right.end(), r.begin(), r.end());
  }
  std::printf("P = %d, %s mode: %zu beat pairs (%zu per frame)\n", P, mode.c_str(), left.size(),
              bpf);
  std::fflush(stdout);

  std::vector<Run<Disp>> runs;
  const std::string tag = "P=" + std::to_string(P) + " " + mode + " ";
  if (o.engine == "rtl" || o.engine == "both") {
    auto rtl = sim::make_disparity_rtl<RtlModel<P>, Params>(
        "bench_disparity_p" + std::to_string(P) + "_" + mode, cfg);
    runs.push_back(drive(tag + "rtl", "rtl", rtl, left, right, bpf,
                         [](auto& mdl) { return mdl.dut().err_o != 0; }));
  }
  if (o.engine == "cpp" || o.engine == "both") {
    // Line buffers and column sums of 1280-pixel rows: keep them off the stack.
    auto cpp = std::make_unique<sim::DisparityModel<Params>>(cfg);
    runs.push_back(drive(tag + "cpp", "cpp", *cpp, left, right, bpf,
                         [](auto& mdl) { return mdl.kernel().error(); }));
  }

  for (const auto& r : runs) {
    std::string problem;
    json j = measure(r, P, mode, o.frames, problem);
    if (!problem.empty()) {
      ok = false;
      std::printf("  FAIL %s P=%d %s: %s\n", r.engine.c_str(), P, mode.c_str(), problem.c_str());
    }
    if (o.reference) {
      // Same cycles in RTL and C++ says nothing about whether either is right at this size
      // (the unit tests run 32-pixel frames): every pixel against the direct reference.
      std::size_t bad = 0, first_bad = 0, invalid = 0;
      const std::uint16_t inv = hls::disparity::invalid_code(cfg);
      for (int k = 0; k < o.frames; ++k) {
        const auto& ref = reference_frame(refs, mode, k, pairs[static_cast<std::size_t>(k)], cfg);
        for (std::size_t b = 0; b < bpf; ++b)
          for (int i = 0; i < P; ++i) {
            const std::size_t px = b * P + static_cast<std::size_t>(i);
            const std::uint16_t got = r.out[static_cast<std::size_t>(k) * bpf + b].px[static_cast<std::size_t>(i)];
            if (got == inv) ++invalid;
            if (got != ref[px] && bad++ == 0) first_bad = static_cast<std::size_t>(k) * W * H + px;
          }
      }
      j["reference_pixels_differing"] = bad;
      j["invalid_fraction"] =
          static_cast<double>(invalid) / (static_cast<double>(o.frames) * W * H);
      if (bad != 0) {
        ok = false;
        std::printf("  FAIL %s P=%d %s: %zu pixels differ from the reference (first: frame %zu, "
                    "x %zu, y %zu)\n",
                    r.engine.c_str(), P, mode.c_str(), bad, first_bad / (W * H),
                    first_bad % W, first_bad / W % H);
      } else {
        std::printf("  %s P=%d %s: every pixel of %d frames equals the direct reference "
                    "(%.1f %% invalid code)\n",
                    r.engine.c_str(), P, mode.c_str(), o.frames,
                    100.0 * j["invalid_fraction"].get<double>());
      }
    }
    rows.push_back({j});
  }
  if (runs.size() == 2) {
    const std::string d = first_difference(runs[0], runs[1]);
    if (d.empty()) {
      std::printf("  P = %d, %s mode: RTL == C++ model: %zu beats, same cycles\n", P,
                  mode.c_str(), runs[0].out.size());
    } else {
      ok = false;
      std::printf("  P = %d, %s mode: RTL != C++ model: %s\n", P, mode.c_str(), d.c_str());
    }
    rows[rows.size() - 2].j["rtl_equals_cpp"] = d.empty();
    rows.back().j["rtl_equals_cpp"] = d.empty();
    if (!d.empty()) rows.back().j["first_difference"] = d;
  }
  std::fflush(stdout);
}

void print_table(const std::vector<Row>& rows) {
  std::printf("\n%-2s %-7s %-4s %10s %7s %9s %9s %9s %9s %9s %9s %8s %10s %7s %8s %8s\n", "P",
              "mode", "eng", "cyc/frame", "=HW/P", "lat_cyc", "lat_rows", "lat_ms", "ms/frame",
              "total_cyc", "frame_ms", "vs6.8ms", "sim_cyc/s", "cpu_s", "lat/9.5", "fr/9.5");
  for (const auto& r : rows) {
    const json& j = r.j;
    const auto cpf = j["cycles_per_frame"].get<std::int64_t>();
    const auto lmin = j["latency_cycles_min"].get<std::int64_t>();
    const auto lmax = j["latency_cycles_max"].get<std::int64_t>();
    const std::string lat =
        lmin == lmax ? std::to_string(lmax) : std::to_string(lmin) + ".." + std::to_string(lmax);
    const bool hp = cpf >= 0;
    // Two frames give the (0, 1) pair, which is not steady state: marked with '*'.
    const std::string star = j["steady"].get<bool>() ? "" : "*";
    std::printf(
        "%-2d %-7s %-4s %10s %7s %9s %9s %9s %9s %9lld %9s %8s %10s %7s %8s %8s\n",
        j["ppc"].get<int>(), j["mode"].get<std::string>().c_str(),
        j["engine"].get<std::string>().c_str(), hp ? (std::to_string(cpf) + star).c_str() : "-",
        hp ? (j["equals_ideal"].get<bool>() ? "yes" : "NO") : "-", lat.c_str(),
        format_number("%.3f", j["latency_rows_max"].get<double>()).c_str(),
        format_number("%.4f", j["latency_ms_at_125mhz"].get<double>()).c_str(),
        hp ? format_number("%.4f", j["ms_per_frame_at_125mhz"].get<double>()).c_str() : "-",
        static_cast<long long>(j["total_cycles"].get<std::int64_t>()),
        format_number("%.3f", j["frame_in_to_out_ms_at_125mhz"].get<double>()).c_str(),
        hp ? format_number("%.3f", j["period_ratio_to_thesis"].get<double>()).c_str() : "-",
        format_number("%.3g", j["sim_cycles_per_cpu_s"].get<double>()).c_str(),
        format_number("%.1f", j["cpu_s"].get<double>()).c_str(),
        format_number("%.4f", j["latency_ratio_to_thesis"].get<double>()).c_str(),
        format_number("%.3f", j["frame_in_to_out_ratio_to_thesis_latency"].get<double>()).c_str());
  }
  std::printf(
      "\n  cyc/frame: output sof to output sof, last two frames (input sof to sof: see per frame);"
      "\n             * = only frames 0 and 1, whose output sofs are not in steady state."
      "\n  lat: output beat i taken - input beat i accepted, frames after the first; rows = /(W/P)."
      "\n  frame_ms: last frame's first input beat to its last output beat, at 125 MHz."
      "\n  sim_cyc/s: simulated cycles per CPU second (std::clock)."
      "\n  thesis FPGA at 125 MHz (Leu Table 5.7): 6.8 ms frame period, 9.5 ms latency."
      "\n  vs6.8ms = ms/frame / 6.8; lat/9.5 = lat_ms / 9.5; fr/9.5 = frame_ms / 9.5 (the thesis"
      "\n  does not say which latency it means; 9.5 > 6.8 suggests a frame-level one).\n");

  std::printf("\nper frame (cycles):\n%-2s %-7s %-4s %5s %10s %10s %10s %10s %10s %10s %11s\n", "P",
              "mode", "eng", "frame", "in_sof", "in_last", "out_sof", "out_last", "in_period",
              "out_period", "in->out");
  for (const auto& r : rows) {
    int k = 0;
    for (const auto& f : r.j["per_frame"]) {
      const auto opt = [&](const char* n) {
        return f.contains(n) ? std::to_string(f[n].get<std::int64_t>()) : std::string("-");
      };
      std::printf("%-2d %-7s %-4s %5d %10lld %10lld %10lld %10lld %10s %10s %11lld\n",
                  r.j["ppc"].get<int>(), r.j["mode"].get<std::string>().c_str(),
                  r.j["engine"].get<std::string>().c_str(), k++,
                  static_cast<long long>(f["in_sof"].get<std::int64_t>()),
                  static_cast<long long>(f["in_last"].get<std::int64_t>()),
                  static_cast<long long>(f["out_sof"].get<std::int64_t>()),
                  static_cast<long long>(f["out_last"].get<std::int64_t>()),
                  opt("in_period").c_str(), opt("out_period").c_str(),
                  static_cast<long long>(f["in_sof_to_out_last"].get<std::int64_t>()));
    }
    std::printf("%-2d %-7s %-4s first frame: beat latency %lld .. %lld cycles\n",
                r.j["ppc"].get<int>(), r.j["mode"].get<std::string>().c_str(),
                r.j["engine"].get<std::string>().c_str(),
                static_cast<long long>(r.j["frame0_latency_cycles_min"].get<std::int64_t>()),
                static_cast<long long>(r.j["frame0_latency_cycles_max"].get<std::int64_t>()));
  }
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  CLI::App app{"Cycles of the disparity stage at 1280 x 480, N = 21, d = 20..64 (RTL and C++)"};
  app.add_option("--left", o.left, "left image, resized to 1280 x 480 grey")
      ->capture_default_str();
  app.add_option("--right", o.right, "right image, resized to 1280 x 480 grey")
      ->capture_default_str();
  bench::add_cycle_options(app, o.ppc, "1, 2", o.engine, o.frames);
  app.add_option("--mode", o.mode, "thesis, opencv or both")
      ->check(CLI::IsMember({"thesis", "opencv", "both"}))
      ->capture_default_str();
  app.add_flag("!--no-reference", o.reference,
               "skip the check of every output pixel against the direct reference (seconds per "
               "frame and mode)");
  app.add_option("--json", o.json_out, "write the results as JSON to this file");
  CLI11_PARSE(app, argc, argv);

  try {
    for (int p : o.ppc)
      if (p != 1 && p != 2) throw std::invalid_argument("--ppc takes 1 and 2");
    cv::Size native;
    const auto pairs = bench_frames(o, native);
    std::printf(
        "disparity at %d x %d, window %d, d = %d..%d (%d candidates), %d frames back to back, "
        "engine %s\ninput: %s / %s (%d x %d), grey, resized with cv::resize INTER_LINEAR to "
        "%d x %d; frame k shifted right by 8 k columns, circularly\n",
        W, H, bench::kDispBenchWindow, bench::kDispBenchDMin,
        bench::kDispBenchDMin + bench::kDispBenchNumDisp - 1, bench::kDispBenchNumDisp, o.frames,
        o.engine.c_str(), std::filesystem::path(o.left).filename().c_str(),
        std::filesystem::path(o.right).filename().c_str(), native.width, native.height, W, H);
    std::fflush(stdout);
    std::vector<std::string> modes;
    if (o.mode == "thesis" || o.mode == "both") modes.push_back("thesis");
    if (o.mode == "opencv" || o.mode == "both") modes.push_back("opencv");
    std::vector<Row> rows;
    RefCache refs;
    bool ok = true;
    for (int p : o.ppc)
      for (const auto& m : modes) {
        if (p == 1) bench_ppc<1>(o, pairs, m, refs, rows, ok);
        if (p == 2) bench_ppc<2>(o, pairs, m, refs, rows, ok);
      }
    print_table(rows);
    scw::bench::write_rows_json(o.json_out, rows);
    std::printf("%s\n", ok ? "OK" : "FAILED (see above)");
    return ok ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "disparity_cycles: %s\n", e.what());
    return 1;
  }
}
