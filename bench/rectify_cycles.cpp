// SPDX-License-Identifier: Apache-2.0
// Measured cycles of the rectify stage at the thesis size (1280 x 480, P = 1, 2, 4): the
// Verilated scw_rectify and its C++ model in the same simulator graph, frames back to back.
//
//   raw_source -> raw_to_rectify -+
//                                  +-> rectify (RTL or C++) -> rectify_to_sink -> sink
//   map_source -> map_to_rectify -+
//
// Prints per P and engine the cycles per frame in steady state, the latency, total cycles,
// ms at 125 MHz, FIFO occupancies and simulation speed; checks every output beat against the
// integer reference and, with --engine both, that RTL and C++ agree beat for beat and cycle for
// cycle. See docs/rectify.md, "Cycles and resources at 1280 x 480".
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench/cycle_bench_options.hpp"
#include "bench/rectify_bench_configs.hpp"
#include "host/pipeline/thesis_figures.hpp"
#include "host/rectify/fixed_map.hpp"
#include "host/rectify/test_maps.hpp"
#include "host/reference/rectify_ref.hpp"
#include "sim/core/components.hpp"
#include "sim/core/frame_beats.hpp"
#include "sim/core/join.hpp"
#include "sim/core/simulator.hpp"
#include "sim/models/rectify_model.hpp"
#include "sim/rtl/rectify_rtl.hpp"
#include "sim/rtl/rtl_params.hpp"
#include "Vbench_rectify_p1.h"
#include "Vbench_rectify_p1_scw_rectify.h"
#include "Vbench_rectify_p2.h"
#include "Vbench_rectify_p2_scw_rectify.h"
#include "Vbench_rectify_p4.h"
#include "Vbench_rectify_p4_scw_rectify.h"

namespace {

using namespace scw;
using host::io::format_number;
using bench::kBenchHeight;
using bench::kBenchRows;
using bench::kBenchWidth;
using host::pipeline::thesis::kClockMhz;
using hls::rectify::RectifyConfig;
using nlohmann::json;

// bench/CMakeLists.txt passes the same values to Verilator with -G.
static_assert(sim::rectify_params_match<Vbench_rectify_p1_scw_rectify, bench::RectifyBench<1>>());
static_assert(sim::rectify_params_match<Vbench_rectify_p2_scw_rectify, bench::RectifyBench<2>>());
static_assert(sim::rectify_params_match<Vbench_rectify_p4_scw_rectify, bench::RectifyBench<4>>());

template <int P>
struct RtlModel {
  using type = sim::ByPpc<P, Vbench_rectify_p1, Vbench_rectify_p2, Vbench_rectify_p4>;
};

struct Options {
  std::string image = SCW_DATA_DIR "/tsukuba/scene1.row3.col3.ppm";
  std::vector<int> ppc{1, 2, 4};
  std::string engine = "both";
  int frames = 3;
  int fifo_depth = 16;
  double angle_deg = 0.5;
  double k1 = -0.02;
  double shift_x = 1.25;
  double shift_y = 2.5;
  std::string json_out;
};

/// A calibration-like map at the thesis size: output (u, v) samples raw position
/// c + (R(angle) (p - c)) (1 + k1 r^2) + shift, r = 1 at the corners (the order in which
/// cv::initUndistortRectifyMap applies a rectifying rotation and then the lens distortion).
rectify::FixedMap bench_map(const Options& o, int frac_bits) {
  constexpr int w = kBenchWidth, h = kBenchHeight;
  const double a = o.angle_deg * 3.14159265358979323846 / 180.0;
  const double c = std::cos(a), s = std::sin(a);
  const double cx = (w - 1) / 2.0, cy = (h - 1) / 2.0, r2n = cx * cx + cy * cy;
  rectify::FixedMap m;
  m.width = w;
  m.height = h;
  m.frac_bits = frac_bits;
  m.points.resize(static_cast<std::size_t>(w) * h);
  for (int v = 0; v < h; ++v)
    for (int u = 0; u < w; ++u) {
      const double ru = c * (u - cx) - s * (v - cy), rv = s * (u - cx) + c * (v - cy);
      const double f = 1.0 + o.k1 * (ru * ru + rv * rv) / r2n;
      m.points[static_cast<std::size_t>(v) * w + u] =
          rectify::quantise_point(cx + ru * f + o.shift_x, cy + rv * f + o.shift_y, w, h, frac_bits);
    }
  return m;
}

/// The frames: the image resized to 1280 x 480 (grey), frame k turned by 8 k columns so that
/// successive frames differ.
std::vector<cv::Mat> bench_frames(const Options& o) {
  cv::Mat img = cv::imread(o.image, cv::IMREAD_GRAYSCALE);
  if (img.empty()) throw std::runtime_error("cannot read '" + o.image + "' as an image");
  cv::Mat big;
  cv::resize(img, big, cv::Size(kBenchWidth, kBenchHeight), 0, 0, cv::INTER_LINEAR);
  std::vector<cv::Mat> frames;
  for (int k = 0; k < o.frames; ++k) {
    const int sh = (8 * k) % kBenchWidth;
    cv::Mat f(big.size(), CV_8UC1);
    if (sh == 0) {
      big.copyTo(f);
    } else {
      big.colRange(kBenchWidth - sh, kBenchWidth).copyTo(f.colRange(0, sh));
      big.colRange(0, kBenchWidth - sh).copyTo(f.colRange(sh, kBenchWidth));
    }
    frames.push_back(f);
  }
  return frames;
}

/// What one run measured.
template <typename Beat>
struct RunResult {
  std::string engine;
  std::int64_t total_cycles = 0;
  std::vector<sim::StageFrame> frames;  // the rectify component, per frame
  std::vector<sim::FrameStamp> raw_in;  // raw_to_rectify, per frame (pops = stage accepts)
  std::vector<sim::FifoReport> fifos;
  std::vector<Beat> out;
  std::uint8_t err = 0;
  double wall_s = 0;
  double cpu_s = 0;  // process CPU time: what speed is quoted in on a shared machine
};

template <typename Params, typename Model, typename ErrFn>
RunResult<typename Params::pixel_beat> run_graph(
    const std::string& engine, Model model, const std::vector<typename Params::pixel_beat>& raw,
    const std::vector<typename Params::map_beat>& map, int fifo_depth, ErrFn err_of) {
  using Pix = typename Params::pixel_beat;
  using Map = typename Params::map_beat;
  constexpr int P = Params::kPpc;
  const std::size_t beats_per_frame =
      static_cast<std::size_t>(kBenchWidth / P) * static_cast<std::size_t>(kBenchHeight);
  const std::size_t expected = raw.size();
  const std::size_t n_frames = expected / beats_per_frame;

  sim::Simulator s;
  // The reader waits up to Rows rows for its first output row: no FIFO moves meanwhile only
  // if the raw side is stuck too, but allow it anyway.
  s.set_deadlock_window(static_cast<std::int64_t>(kBenchRows + 2) * (kBenchWidth / P));
  auto& raw_f = s.fifo<Pix>("raw_to_rectify", fifo_depth);
  auto& map_f = s.fifo<Map>("map_to_rectify", fifo_depth);
  auto& out_f = s.fifo<Pix>("rectify_to_sink", fifo_depth);
  s.add<sim::Source<Pix>>("raw_source", raw_f, raw);
  s.add<sim::Source<Map>>("map_source", map_f, map);
  auto& stage = s.add<sim::JoinComponent<Model>>("rectify", std::move(model), raw_f, map_f, out_f);
  auto& sink = s.add<sim::Sink<Pix>>("sink", out_f);

  const std::clock_t c0 = std::clock();
  const auto t0 = std::chrono::steady_clock::now();
  auto last_print = t0;
  const auto done = [&] {
    const std::size_t got = sink.beats().size();
    if ((s.cycle() & 0xffff) == 0) {
      const auto now = std::chrono::steady_clock::now();
      if (std::chrono::duration<double>(now - last_print).count() >= 5.0) {
        last_print = now;
        const double el = std::chrono::duration<double>(now - t0).count();
        std::fprintf(stderr,
                     "  [%s P=%d] cycle %lld, %.2f of %zu frames out, %.2f Mcycles/s (wall)\n",
                     engine.c_str(), P, static_cast<long long>(s.cycle()),
                     static_cast<double>(got) / static_cast<double>(beats_per_frame), n_frames,
                     static_cast<double>(s.cycle()) / el / 1e6);
      }
    }
    return got >= expected;
  };
  s.run_until(done, static_cast<std::int64_t>(n_frames + 2) * 2 *
                        static_cast<std::int64_t>(beats_per_frame));
  const auto t1 = std::chrono::steady_clock::now();
  const std::clock_t c1 = std::clock();

  RunResult<Pix> r;
  r.engine = engine;
  r.wall_s = std::chrono::duration<double>(t1 - t0).count();
  r.cpu_s = static_cast<double>(c1 - c0) / CLOCKS_PER_SEC;
  r.total_cycles = s.cycle();
  const auto rep = s.report();
  for (const auto& st : rep.stages)
    if (st.name == "rectify") r.frames = st.frames;
  r.fifos = rep.fifos;
  r.raw_in = raw_f.frames();
  r.out = sink.beats();
  r.err = err_of(stage.model());
  return r;
}

struct Row {  // one line of the summary table
  int ppc = 0;
  std::string engine;
  json j;
};

template <int P>
void bench_ppc(const Options& o, const std::vector<cv::Mat>& imgs, std::vector<Row>& rows,
               bool& ok) {
  using Params = bench::RectifyBench<P>;
  using Pix = typename Params::pixel_beat;
  using Map = typename Params::map_beat;
  constexpr int W = kBenchWidth, H = kBenchHeight;
  constexpr std::int64_t kBeatsPerRow = W / P;
  constexpr std::int64_t kIdeal = kBeatsPerRow * H;

  const auto tprep = std::chrono::steady_clock::now();
  const rectify::FixedMap map = bench_map(o, Params::kFracBits);
  const rectify::RowWindow win = rectify::row_window(map);
  const rectify::RectifyPlan plan = rectify::plan_for_stage({win}, Params::kRows, "the bench map");
  const RectifyConfig cfg{W, H, plan.lead_rows};

  std::vector<Pix> raw;
  std::vector<Map> mapb;
  std::vector<std::uint8_t> expected;
  const auto map_frame = sim::frame_beats_of<Map>(map.points.data(), W, H);
  for (const auto& img : imgs) {
    const auto r = sim::frame_beats_of<Pix>(img.ptr<std::uint8_t>(0), W, H);
    raw.insert(raw.end(), r.begin(), r.end());
    mapb.insert(mapb.end(), map_frame.begin(), map_frame.end());
    const auto e = reference::rectify_reference(img.ptr<std::uint8_t>(0), W, H, map.points.data(),
                                                W, H, Params::kFracBits);
    expected.insert(expected.end(), e.begin(), e.end());
  }
  const double prep_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - tprep).count();
  std::printf(
      "P = %d: map rows v%+d .. v%+d, lead D = %d, %d of %d raw rows needed; %zu raw + %zu map "
      "beats (%.1f s to prepare)\n",
      P, win.dy_min, win.dy_max, plan.lead_rows, plan.rows_needed, Params::kRows, raw.size(),
      mapb.size(), prep_s);
  std::fflush(stdout);

  std::vector<RunResult<Pix>> results;
  if (o.engine == "rtl" || o.engine == "both") {
    using VM = typename RtlModel<P>::type;
    results.push_back(run_graph<Params>(
        "rtl", sim::make_rectify_rtl<VM, Params>("bench_rectify_p" + std::to_string(P), cfg), raw,
        mapb, o.fifo_depth, [](auto& m) { return static_cast<std::uint8_t>(m.dut().err_o); }));
  }
  if (o.engine == "cpp" || o.engine == "both") {
    results.push_back(run_graph<Params>("cpp", sim::RectifyModel<Params>(cfg), raw, mapb,
                                        o.fifo_depth, [](auto& m) { return m.kernel().error(); }));
  }

  for (const auto& r : results) {
    // Every output pixel against the integer reference.
    std::size_t bad = 0, first_bad = 0;
    if (r.out.size() != expected.size() / P) {
      bad = 1;
    } else {
      for (std::size_t i = 0; i < r.out.size(); ++i)
        for (int k = 0; k < P; ++k)
          if (r.out[i].px[static_cast<std::size_t>(k)] !=
              expected[i * P + static_cast<std::size_t>(k)]) {
            if (bad++ == 0) first_bad = i;
          }
    }
    const bool frames_ok = static_cast<int>(r.frames.size()) == o.frames;
    if (bad != 0 || r.err != 0 || !frames_ok) {
      ok = false;
      std::printf(
          "  FAIL %s P=%d: %zu beats differ from the reference (first at beat %zu), err=%d,"
          " %zu frames seen\n",
          r.engine.c_str(), P, bad, first_bad, r.err, r.frames.size());
    }

    json j;
    j["ppc"] = P;
    j["engine"] = r.engine;
    j["width"] = W;
    j["height"] = H;
    j["stage_rows"] = Params::kRows;
    j["lead_rows"] = plan.lead_rows;
    j["rows_needed"] = plan.rows_needed;
    j["map_dy"] = {win.dy_min, win.dy_max};
    j["frames"] = o.frames;
    j["fifo_depth"] = o.fifo_depth;
    j["ideal_cycles_per_frame"] = kIdeal;
    j["total_cycles"] = r.total_cycles;
    j["total_ms_at_125mhz"] = static_cast<double>(r.total_cycles) / (kClockMhz * 1e3);
    json jf = json::array();
    for (std::size_t k = 0; k < r.frames.size(); ++k) {
      const auto& f = r.frames[k];
      json x{{"first_in", f.first_in},
             {"last_in", f.last_in},
             {"first_out", f.first_out},
             {"last_out", f.last_out}};
      if (k < r.raw_in.size()) x["raw_last_in"] = r.raw_in[k].last_pop;
      if (k > 0) x["period"] = f.last_out - r.frames[k - 1].last_out;
      jf.push_back(x);
    }
    j["per_frame"] = jf;
    std::int64_t period = -1;
    if (r.frames.size() >= 2)
      period = r.frames.back().last_out - r.frames[r.frames.size() - 2].last_out;
    j["cycles_per_frame"] = period;
    j["ms_per_frame_at_125mhz"] = static_cast<double>(period) / (kClockMhz * 1e3);
    const std::int64_t lat = r.frames.empty() ? -1 : r.frames[0].first_out - r.frames[0].first_in;
    j["latency_cycles"] = lat;
    j["latency_rows"] = static_cast<double>(lat) / static_cast<double>(kBeatsPerRow);
    j["latency_ms_at_125mhz"] = static_cast<double>(lat) / (kClockMhz * 1e3);
    // From the frame's last raw beat in to its last output beat: the rows still in flight.
    const std::int64_t tail =
        r.frames.empty() || r.raw_in.empty() ? -1 : r.frames[0].last_out - r.raw_in[0].last_pop;
    j["last_raw_in_to_last_out_cycles"] = tail;
    json jq = json::object();
    for (const auto& q : r.fifos)
      jq[q.name] = {{"depth", q.depth}, {"max_occupancy", q.max_occupancy}};
    j["fifos"] = jq;
    j["wall_s"] = r.wall_s;
    j["cpu_s"] = r.cpu_s;
    j["sim_cycles_per_s"] = static_cast<double>(r.total_cycles) / r.wall_s;
    j["sim_cycles_per_cpu_s"] = static_cast<double>(r.total_cycles) / r.cpu_s;
    j["reference_beats_differing"] = bad;
    j["err"] = r.err;
    rows.push_back({P, r.engine, j});
  }

  if (results.size() == 2) {
    const auto& a = results[0];
    const auto& b = results[1];
    bool same = a.out == b.out && a.total_cycles == b.total_cycles &&
                a.frames.size() == b.frames.size() && a.fifos.size() == b.fifos.size();
    for (std::size_t k = 0; same && k < a.frames.size(); ++k)
      same = a.frames[k].first_in == b.frames[k].first_in &&
             a.frames[k].last_in == b.frames[k].last_in &&
             a.frames[k].first_out == b.frames[k].first_out &&
             a.frames[k].last_out == b.frames[k].last_out;
    for (std::size_t k = 0; same && k < a.fifos.size(); ++k)
      same = a.fifos[k].max_occupancy == b.fifos[k].max_occupancy &&
             a.fifos[k].beats == b.fifos[k].beats;
    std::printf(
        "P = %d: RTL and C++ model %s (output beats, total cycles, per-frame stamps, FIFO "
        "occupancies)\n",
        P, same ? "agree" : "DIFFER");
    if (!same) ok = false;
    rows[rows.size() - 2].j["rtl_equals_cpp"] = same;
    rows.back().j["rtl_equals_cpp"] = same;
  }
  std::fflush(stdout);
}

void print_table(const std::vector<Row>& rows) {
  std::printf("\n%-3s %-6s %12s %12s %8s %11s %8s %9s %11s %9s %9s %18s %13s %8s %8s\n", "P",
              "engine", "cyc/frame", "ideal", "ratio", "latency", "lat_rows", "lat_ms", "total_cyc",
              "ms/frame", "total_ms", "maxocc raw/map/out", "sim_cyc/cpu_s", "cpu_s", "wall_s");
  for (const auto& r : rows) {
    const json& j = r.j;
    const auto occ = [&](const char* n) { return j["fifos"][n]["max_occupancy"].get<int>(); };
    std::ostringstream q;
    q << occ("raw_to_rectify") << "/" << occ("map_to_rectify") << "/" << occ("rectify_to_sink");
    const auto cpf = j["cycles_per_frame"].get<std::int64_t>();
    const auto ideal = j["ideal_cycles_per_frame"].get<std::int64_t>();
    // One frame has no period: "-".
    const bool has_period = cpf >= 0;
    std::printf("%-3d %-6s %12s %12lld %8s %11lld %8s %9s %11lld %9s %9s %18s %13s %8s %8s\n",
                r.ppc, r.engine.c_str(), has_period ? std::to_string(cpf).c_str() : "-",
                static_cast<long long>(ideal),
                has_period
                    ? format_number("%.4f", static_cast<double>(cpf) / static_cast<double>(ideal)).c_str()
                    : "-",
                static_cast<long long>(j["latency_cycles"].get<std::int64_t>()),
                format_number("%.3f", j["latency_rows"].get<double>()).c_str(),
                format_number("%.3f", j["latency_ms_at_125mhz"].get<double>()).c_str(),
                static_cast<long long>(j["total_cycles"].get<std::int64_t>()),
                has_period ? format_number("%.3f", j["ms_per_frame_at_125mhz"].get<double>()).c_str() : "-",
                format_number("%.3f", j["total_ms_at_125mhz"].get<double>()).c_str(), q.str().c_str(),
                format_number("%.3g", j["sim_cycles_per_cpu_s"].get<double>()).c_str(),
                format_number("%.2f", j["cpu_s"].get<double>()).c_str(),
                format_number("%.2f", j["wall_s"].get<double>()).c_str());
  }
  std::printf("\nper frame (rectify stage; cycles; period = last_out - previous last_out):\n");
  std::printf("%-3s %-6s %5s %10s %10s %10s %10s %10s %10s\n", "P", "engine", "frame", "first_in",
              "raw_last", "first_out", "last_out", "period", "tail");
  for (const auto& r : rows) {
    int k = 0;
    for (const auto& f : r.j["per_frame"]) {
      const auto last_out = f["last_out"].get<std::int64_t>();
      const auto raw_last = f.value("raw_last_in", std::int64_t{-1});
      std::printf(
          "%-3d %-6s %5d %10lld %10lld %10lld %10lld %10s %10lld\n", r.ppc, r.engine.c_str(), k++,
          static_cast<long long>(f["first_in"].get<std::int64_t>()),
          static_cast<long long>(raw_last),
          static_cast<long long>(f["first_out"].get<std::int64_t>()),
          static_cast<long long>(last_out),
          f.contains("period") ? std::to_string(f["period"].get<std::int64_t>()).c_str() : "-",
          static_cast<long long>(last_out - raw_last));
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  CLI::App app{"Cycles of the rectify stage at 1280 x 480 (RTL and C++ model, P = 1, 2, 4)"};
  app.add_option("--image", o.image, "raw image, resized to 1280 x 480 grey")
      ->capture_default_str();
  bench::add_cycle_options(app, o.ppc, "1, 2, 4", o.engine, o.frames);
  app.add_option("--fifo-depth", o.fifo_depth, "depth of the three FIFOs")
      ->check(CLI::Range(1, 1 << 20))
      ->capture_default_str();
  app.add_option("--angle", o.angle_deg, "map: rotation, degrees")->capture_default_str();
  app.add_option("--k1", o.k1, "map: radial term (r = 1 at the corners; < 0 barrel)")
      ->capture_default_str();
  app.add_option("--shift-x", o.shift_x, "map: horizontal shift, pixels")->capture_default_str();
  app.add_option("--shift-y", o.shift_y, "map: vertical shift, rows")->capture_default_str();
  app.add_option("--json", o.json_out, "write the results as JSON to this file");
  CLI11_PARSE(app, argc, argv);

  try {
    for (int p : o.ppc)
      if (p != 1 && p != 2 && p != 4) throw std::invalid_argument("--ppc takes 1, 2 and 4");
    const auto imgs = bench_frames(o);
    std::printf(
        "rectify at %d x %d, %d raw rows, %d frames back to back, engine %s, FIFOs %d deep\n"
        "map: rotation %.3g deg, k1 %.3g, shift (%.3g, %.3g) px; image %s\n",
        kBenchWidth, kBenchHeight, kBenchRows, o.frames, o.engine.c_str(), o.fifo_depth,
        o.angle_deg, o.k1, o.shift_x, o.shift_y, o.image.c_str());
    std::vector<Row> rows;
    bool ok = true;
    for (int p : o.ppc) {
      if (p == 1) bench_ppc<1>(o, imgs, rows, ok);
      if (p == 2) bench_ppc<2>(o, imgs, rows, ok);
      if (p == 4) bench_ppc<4>(o, imgs, rows, ok);
    }
    print_table(rows);
    scw::bench::write_rows_json(o.json_out, rows);
    std::printf("%s\n",
                ok ? "OK: every output beat equals the integer reference" : "FAILED (see above)");
    return ok ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "rectify_cycles: %s\n", e.what());
    return 1;
  }
}
