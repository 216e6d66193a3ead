// SPDX-License-Identifier: Apache-2.0
// `scw stream`: streams an image through the line buffer in sim/ (C++ twin or Verilated RTL),
// checks every beat against a whole-image reference, and writes the report and golden vectors
// (the work is host/pipeline/stream_run).
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

#include "hls/common/line_buffer.hpp"
#include "host/cli/commands.hpp"
#include "host/pipeline/stream_line_buffer.hpp"
#include "host/pipeline/thesis_figures.hpp"
#include "sim/rtl/rtl_params.hpp"
#include "Vcli_line_buffer_p1.h"
#include "Vcli_line_buffer_p1_scw_line_buffer.h"
#include "Vcli_line_buffer_p2.h"
#include "Vcli_line_buffer_p2_scw_line_buffer.h"
#include "Vcli_line_buffer_p4.h"
#include "Vcli_line_buffer_p4_scw_line_buffer.h"

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
using RtlModel = sim::ByPpc<P, Vcli_line_buffer_p1, Vcli_line_buffer_p2, Vcli_line_buffer_p4>;

template <int P>
void run(const host::pipeline::StreamOptions& o, const cv::Mat& grey) {
  const auto r = host::pipeline::stream_line_buffer<DemoParams<P>, RtlModel<P>>(o, grey, std::cerr);
  std::cout << r.report.text() << "\n";
  const auto& lb = r.report.stages[1].frames;
  if (lb.size() >= 2) {
    const auto period = lb[1].first_in - lb[0].first_in;
    std::cout << "frame period " << period << " cycles = " << period / (kClockMhz * 1e3)
              << " ms at " << kClockMhz << " MHz (" << r.frame_beats << " beats of " << P
              << " px per frame)\n";
  }
  std::cout << "latency through the line buffer: " << lb[0].first_out - lb[0].first_in
            << " cycles; all " << r.beats << " beats equal the whole-image reference\n";
  host::pipeline::write_stream_files(o, r, grey);
  const std::filesystem::path dir(o.out_dir);
  std::cout << "wrote " << (dir / "report.json").string() << " and " << (dir / "vectors").string()
            << "/\n";
}

}  // namespace

void add_stream_command(CLI::App& app) {
  auto o = std::make_shared<host::pipeline::StreamOptions>();
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
    const cv::Mat img = host::pipeline::read_stream_image(*o, kMaxWidthPx);
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
