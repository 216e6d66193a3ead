// SPDX-License-Identifier: Apache-2.0
// `scw stream`: streams an image through the line buffer in sim/ (C++ twin or Verilated RTL),
// checks every beat against a whole-image reference, and writes the report and golden vectors.
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <string>

#include "Vcli_line_buffer_p1.h"
#include "Vcli_line_buffer_p1_scw_line_buffer.h"
#include "Vcli_line_buffer_p2.h"
#include "Vcli_line_buffer_p2_scw_line_buffer.h"
#include "Vcli_line_buffer_p4.h"
#include "Vcli_line_buffer_p4_scw_line_buffer.h"
#include "hls/common/line_buffer.hpp"
#include "host/cli/commands.hpp"
#include "host/io/image_file.hpp"
#include "host/pipeline/thesis_figures.hpp"
#include "host/reference/line_buffer_ref.hpp"
#include "host/vectors/vector_set.hpp"
#include "sim/components.hpp"
#include "sim/frame_beats.hpp"
#include "sim/pipeline_shell.hpp"
#include "sim/rtl_params.hpp"
#include "sim/rtl_stream.hpp"

namespace scw::cli {
namespace {

constexpr int kMaxWidthPx = 1280;  // the thesis camera's row
constexpr int kRows = 3;
using host::pipeline::thesis::kClockMhz;
template <int P>
using DemoParams = hls::LineBufferParams<P, kMaxWidthPx, kRows>;

static_assert(sim::line_buffer_params_match<Vcli_line_buffer_p1_scw_line_buffer, DemoParams<1>>());
static_assert(sim::line_buffer_params_match<Vcli_line_buffer_p2_scw_line_buffer, DemoParams<2>>());
static_assert(sim::line_buffer_params_match<Vcli_line_buffer_p4_scw_line_buffer, DemoParams<4>>());

template <int P>
struct RtlModel {
  using type = sim::ByPpc<P, Vcli_line_buffer_p1, Vcli_line_buffer_p2, Vcli_line_buffer_p4>;
};

struct Options {
  std::string image;
  int ppc = 1;
  std::string engine = "rtl";
  int frames = 2;
  std::string stalls = "none";
  std::string out_dir = "out/stream";
  std::vector<int> roi;  // x y w h, empty = whole image
};

nlohmann::json report_json(const sim::SimReport& r) {
  nlohmann::json j;
  j["cycles"] = r.cycles;
  for (const auto& f : r.fifos)
    j["fifos"].push_back({{"name", f.name},
                          {"producer", f.producer},
                          {"consumer", f.consumer},
                          {"depth", f.depth},
                          {"max_occupancy", f.max_occupancy},
                          {"beats", f.beats}});
  for (const auto& s : r.stages) {
    nlohmann::json st{{"name", s.name}, {"frames", nlohmann::json::array()}};
    for (const auto& f : s.frames)
      st["frames"].push_back({{"first_in", f.first_in},
                              {"last_in", f.last_in},
                              {"first_out", f.first_out},
                              {"last_out", f.last_out}});
    j["stages"].push_back(st);
  }
  return j;
}

template <int P>
void run(const Options& o, const cv::Mat& grey) {
  using Params = DemoParams<P>;
  using Kernel = hls::LineBuffer<std::uint8_t, Params>;
  using In = typename Kernel::in_type;
  using Out = typename Kernel::out_type;
  const int w = grey.cols, h = grey.rows;

  // Beats of one frame, and the expected windows by indexing the image directly.
  const cv::Mat img = grey.isContinuous() ? grey : grey.clone();
  const auto frame = sim::frame_beats<P>(img.ptr<std::uint8_t>(), w, h);
  const auto expect = reference::line_buffer_reference<P, kRows>(img.ptr<std::uint8_t>(), w, h);
  std::vector<In> in;
  for (int f = 0; f < o.frames; ++f) in.insert(in.end(), frame.begin(), frame.end());

  sim::Simulator s;
  auto& f_in = s.fifo<In>("source_to_line_buffer", 4);
  auto& f_out = s.fifo<Out>("line_buffer_to_sink", 4);
  const auto stalls = sim::StallPattern::parse(o.stalls);
  auto& src = s.add<sim::Source<In>>("source", f_in, in, stalls);
  if (o.engine == "rtl") {
    using Rtl = sim::RtlStream<typename RtlModel<P>::type, In, Out>;
    s.add<sim::StreamComponent<Rtl>>("line_buffer", Rtl("line_buffer"), f_in, f_out);
  } else {
    using Cpp = sim::PipelineShell<Kernel, Params::kLatency>;
    s.add<sim::StreamComponent<Cpp>>("line_buffer", Cpp(), f_in, f_out);
  }
  auto& sink = s.add<sim::Sink<Out>>("sink", f_out, stalls);

  std::size_t reported = 0;
  s.run_until(
      [&] {
        const std::size_t done_frames = sink.beats().size() / frame.size();
        if (done_frames > reported) {
          reported = done_frames;
          std::cerr << "  frame " << done_frames << "/" << o.frames << " done at cycle "
                    << s.cycle() << "\n";
        }
        return src.done() && sink.beats().size() == in.size();
      },
      static_cast<std::int64_t>(in.size()) * 20 + 1000);

  std::size_t wrong = 0;
  for (std::size_t i = 0; i < sink.beats().size(); ++i)
    if (sink.beats()[i] != expect[i % expect.size()]) ++wrong;
  if (wrong != 0)
    throw std::runtime_error(std::to_string(wrong) + " of " + std::to_string(in.size()) +
                             " beats differ from the whole-image reference (engine " + o.engine +
                             ")");

  const auto rep = s.report();
  std::cout << rep.text() << "\n";
  const auto& lb = rep.stages[1].frames;
  if (lb.size() >= 2) {
    const auto period = lb[1].first_in - lb[0].first_in;
    std::cout << "frame period " << period << " cycles = " << period / (kClockMhz * 1e3)
              << " ms at " << kClockMhz << " MHz (" << frame.size() << " beats of " << P
              << " px per frame)\n";
  }
  std::cout << "latency through the line buffer: " << lb[0].first_out - lb[0].first_in
            << " cycles; all " << in.size() << " beats equal the whole-image reference\n";

  const std::filesystem::path dir(o.out_dir);
  std::filesystem::create_directories(dir);
  nlohmann::json j = report_json(rep);
  j["engine"] = o.engine;
  j["ppc"] = P;
  j["clock_mhz"] = kClockMhz;
  std::ofstream(dir / "report.json") << j.dump(2) << "\n";

  // Golden vectors of one frame, replayable in any simulator with $readmemh.
  vectors::VectorWriter vw(dir / "vectors", "line_buffer",
                           {{"ppc", P},
                            {"max_width_px", kMaxWidthPx},
                            {"rows", kRows},
                            {"width", w},
                            {"height", h},
                            {"latency", Params::kLatency}},
                           "scw_line_buffer: each beat with the same columns of the 2 rows above");
  const auto hex_in = sim::pack_all(frame);
  const auto hex_out = sim::pack_all(expect);
  vw.add_image("input.png", "input", grey);
  vw.add_hex("input.hex", "input", hex_in, vectors::pixel_beat_layout(P, 8));
  vw.add_hex("expected.hex", "expected", hex_out, vectors::pixel_beat_layout(P * kRows, 8));
  vw.finish();
  std::cout << "wrote " << (dir / "report.json").string() << " and " << (dir / "vectors").string()
            << "/\n";
}

}  // namespace

void add_stream_command(CLI::App& app) {
  auto o = std::make_shared<Options>();
  auto* cmd = app.add_subcommand(
      "stream", "Stream an image through the line buffer in the cycle simulator (C++ or RTL)");
  cmd->add_option("--image", o->image, "Input image (colour is converted to grey)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--ppc", o->ppc, "Pixels per beat")->check(CLI::IsMember({1, 2, 4}));
  cmd->add_option("--engine", o->engine, "cpp (C++ twin) or rtl (Verilated)")
      ->check(CLI::IsMember({"cpp", "rtl"}));
  cmd->add_option("--frames", o->frames, "Frames back to back")->check(CLI::Range(1, 1000));
  cmd->add_option("--stalls", o->stalls, "none, idle, backpressure, both or random:<seed>");
  cmd->add_option("--out-dir", o->out_dir, "Where report.json and vectors/ go");
  cmd->add_option("--roi", o->roi, "Stream only this rectangle: X Y W H")->expected(4);
  cmd->callback([o] {
    sim::StallPattern::parse(o->stalls);  // reject a bad pattern before any work
    cv::Mat img = host::io::read_grey_image(o->image);
    if (!o->roi.empty()) {
      const cv::Rect r(o->roi[0], o->roi[1], o->roi[2], o->roi[3]);
      if (r.width <= 0 || r.height <= 0 || (r & cv::Rect(0, 0, img.cols, img.rows)) != r)
        throw std::runtime_error("--roi " + std::to_string(r.x) + " " + std::to_string(r.y) + " " +
                                 std::to_string(r.width) + " " + std::to_string(r.height) +
                                 " is not inside the " + std::to_string(img.cols) + " x " +
                                 std::to_string(img.rows) + " image");
      img = img(r).clone();
    }
    if (img.cols > kMaxWidthPx || img.cols % o->ppc != 0 || img.cols / o->ppc < 2)
      throw std::runtime_error("image '" + o->image + "' is " + std::to_string(img.cols) +
                               " px wide: the line buffer holds rows of up to " +
                               std::to_string(kMaxWidthPx) + " px, in whole beats of " +
                               std::to_string(o->ppc) + " px; crop or resize it");
    std::cerr << "streaming " << img.cols << " x " << img.rows << " x " << o->frames
              << " frames, P = " << o->ppc << ", engine " << o->engine << ", stalls " << o->stalls
              << "\n";
    switch (o->ppc) {
      case 1:
        run<1>(*o, img);
        break;
      case 2:
        run<2>(*o, img);
        break;
      default:
        run<4>(*o, img);
        break;
    }
  });
}

}  // namespace scw::cli
