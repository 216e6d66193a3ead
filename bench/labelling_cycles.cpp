// SPDX-License-Identifier: Apache-2.0
// Measured cycles of the labelling stage at the thesis size (1280 x 480, 8 x 4 tiles): the
// Verilated scw_labelling and its C++ model (clock-for-clock twins), each driven by a plain loop
// with frames back to back (sim::run_stream's per-cycle trace would be too big at this size).
//
// For each map it prints the input cycles per frame (one beat per clock means cycles = pixels;
// more are the clocks the stage held in_ready low because its edge queue was full), the cycles
// from the frame's last pixel to its last word (status), the frame period with frames back to
// back, objects and flags, and checks the objects against the flood-fill reference.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench/labelling_bench_configs.hpp"
#include "host/io/tsukuba.hpp"
#include "host/labelling/run_model.hpp"
#include "host/labelling/second_pass.hpp"
#include "host/reference/labelling_ref.hpp"
#include "sim/core/frame_beats.hpp"
#include "sim/models/labelling_model.hpp"
#include "sim/rtl/labelling_rtl.hpp"
#include "Vbench_labelling.h"
#include "Vbench_labelling_scw_labelling.h"

namespace {

using namespace scw;
using hls::labelling::LabelPacket;
using hls::labelling::LabellingConfig;
using Params = bench::LabellingBench;
constexpr int W = bench::kLabBenchWidth;
constexpr int H = bench::kLabBenchHeight;
static_assert(sim::labelling_params_match<Vbench_labelling_scw_labelling, Params>(),
              "bench/CMakeLists.txt must build scw_labelling with LabellingBench's parameters");

struct Map {
  std::string name;
  cv::Mat d;  // CV_16UC1, W x H, Q11.4
};

/// Per frame: cycle of its first and last accepted beat, and of its status word.
struct FrameTimes {
  std::int64_t first_in = -1, last_in = -1, status = -1;
  hls::labelling::FrameStatus st;
  std::vector<hls::labelling::Object> objects;
};

/// Both engines start from reset (the parent RAM's clearing is before the first beat is taken).
template <typename Model>
std::vector<FrameTimes> run(Model& model, const Map& m, int frames) {
  using Beat = Params::in_beat;
  const auto one = sim::frame_beats_of<Beat>(m.d.ptr<std::uint16_t>(), W, H);
  std::vector<FrameTimes> t(static_cast<std::size_t>(frames));
  std::size_t next = 0, total = one.size() * static_cast<std::size_t>(frames);
  int done = 0;
  for (std::int64_t c = 0; done < frames; ++c) {
    const bool valid = next < total;
    const Beat& b = one[next % one.size()];
    const auto o = model.eval(valid, b, true);
    model.tick();
    if (valid && o.in_ready) {
      auto& f = t[next / one.size()];
      if (f.first_in < 0) f.first_in = c;
      f.last_in = c;
      ++next;
    }
    if (o.out_valid) {
      auto& f = t[static_cast<std::size_t>(done)];
      if (o.out.data.is_status) {
        f.status = c;
        f.st = o.out.data.status;
        ++done;
      } else {
        f.objects.push_back(o.out.data.object);
      }
    }
    if (c > 100LL * static_cast<std::int64_t>(total)) throw std::runtime_error("no progress");
  }
  return t;
}

cv::Mat fit(const cv::Mat& d16) {  // nearest-neighbour to W x H, as the thesis frame
  cv::Mat out;
  cv::resize(d16, out, cv::Size(W, H), 0, 0, cv::INTER_NEAREST);
  return out;
}

Map random_field(double density) {
  cv::Mat d(H, W, CV_16UC1, cv::Scalar(0));
  cv::RNG rng(1234);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x)
      if (rng.uniform(0.0, 1.0) < density)
        d.at<std::uint16_t>(y, x) =
            static_cast<std::uint16_t>(16 * (20 + (x / 40 + y / 30) % 45) + rng.uniform(-24, 24));
  return {"random field, density " + std::to_string(density).substr(0, 4), d};
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Cycles of the labelling stage at 1280 x 480: scw_labelling and its C++ model"};
  std::vector<std::string> maps_in;
  int frames = 2, min_area = 1;
  bool reference = true;
  app.add_option("--disparity", maps_in,
                 "16-bit disparity maps (x16, e.g. from `scw disparity --out16`), resized to "
                 "1280 x 480 by nearest neighbour");
  app.add_option("--frames", frames, "frames back to back per map")->check(CLI::Range(1, 8));
  app.add_option("--min-area", min_area, "MinArea");
  app.add_flag("!--no-reference", reference, "skip the flood-fill check");

  std::string engine = "cpp";
  app.add_option("--engine", engine, "cpp, rtl or both (both must agree on every cycle count "
                                     "and object)")
      ->check(CLI::IsMember({"cpp", "rtl", "both"}));
  CLI11_PARSE(app, argc, argv);

  std::vector<Map> maps;
  {
    const cv::Mat g16 = scw::host::io::read_tsukuba_truth(SCW_DATA_DIR "/tsukuba", CV_16UC1);
    maps.push_back({"Tsukuba ground truth, resized", fit(g16)});
  }
  for (const auto& p : maps_in) {
    cv::Mat d = cv::imread(p, cv::IMREAD_UNCHANGED);
    if (d.empty() || d.channels() != 1 || (d.depth() != CV_16U && d.depth() != CV_16S))
      throw std::runtime_error("'" + p + "' is not a 16-bit disparity map");
    cv::Mat d16 = d;
    if (d.depth() == CV_16S) {
      d16 = cv::max(d, 0);
      d16.convertTo(d16, CV_16U);
    }
    maps.push_back({p, fit(d16)});
  }
  maps.push_back(random_field(0.3));
  maps.push_back(random_field(0.7));

  const LabellingConfig cfg =
      labelling::grid_config(W, H, bench::kLabBenchTilesX, bench::kLabBenchTilesY, 0, min_area);
  std::printf("labelling at %d x %d, %d x %d tiles of %d x %d, %d labels/tile, %d objects, "
              "MinArea %d, %d frames back to back; %.0f MHz\n",
              W, H, bench::kLabBenchTilesX, bench::kLabBenchTilesY, cfg.tile_w, cfg.tile_h,
              bench::kLabBenchLabels, bench::kLabBenchObjects, min_area, frames,
              bench::kLabClockMhz);
  std::printf("%-40s %9s %8s %10s %10s %8s %8s %s\n", "map", "in cyc", "stalls", "tail cyc",
              "period", "ms/frm", "objects", "flags");
  auto same = [](const std::vector<FrameTimes>& a, const std::vector<FrameTimes>& b) {
    for (std::size_t i = 0; i < a.size(); ++i)
      if (a[i].first_in != b[i].first_in || a[i].last_in != b[i].last_in ||
          a[i].status != b[i].status || !(a[i].st == b[i].st) || a[i].objects != b[i].objects)
        return false;
    return true;
  };
  for (const auto& m : maps) {
    const auto t0 = std::chrono::steady_clock::now();
    std::vector<FrameTimes> t, t_rtl;
    if (engine != "rtl") {
      auto model = std::make_unique<sim::LabellingModel<Params>>(cfg);
      t = run(*model, m, frames);
    }
    if (engine != "cpp") {
      auto rtl = sim::make_labelling_rtl<Vbench_labelling, Params>("labelling", cfg);
      t_rtl = run(rtl, m, frames);
      if (t.empty()) t = t_rtl;
    }
    const double secs =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const auto& f = t.back();
    const std::int64_t in_cycles = f.last_in - f.first_in + 1;
    const std::int64_t period = frames > 1 ? t[1].status - t[0].status : f.status - f.first_in + 1;
    std::string flags;
    if (f.st.tile_overflow) flags += "tile_overflow ";
    if (f.st.object_overflow) flags += "object_overflow ";
    if (f.st.stream_error) flags += "stream_error ";
    std::printf("%-40s %9lld %8lld %10lld %10lld %8.3f %8u %s(%s, %.1f s)\n", m.name.c_str(),
                static_cast<long long>(in_cycles), static_cast<long long>(in_cycles - W * H),
                static_cast<long long>(f.status - f.last_in), static_cast<long long>(period),
                static_cast<double>(period) / (bench::kLabClockMhz * 1000.0), f.st.objects,
                flags.c_str(), engine.c_str(), secs);
    if (engine == "both") {
      if (!same(t, t_rtl)) {
        std::printf("  MISMATCH: RTL and C++ model differ\n");
        return 1;
      }
      std::printf("  RTL = C++ model: every frame's cycles, status and objects\n");
    }
    if (reference && !f.st.tile_overflow && !f.st.object_overflow) {
      const auto ref = reference::labelling_reference(m.d.ptr<std::uint16_t>(), W, H, cfg);
      if (labelling::raster_sorted(f.objects) != ref.objects) {
        std::printf("  MISMATCH against the flood-fill reference\n");
        return 1;
      }
      std::printf("  = flood-fill reference (%zu objects)\n", ref.objects.size());
    }
  }
  return 0;
}
