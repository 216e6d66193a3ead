// SPDX-License-Identifier: Apache-2.0
// `scw stream`'s run: an image streamed frame after frame through the line buffer in sim/ (its
// C++ twin or a Verilated model), every beat checked against a whole-image reference. Apart from
// stream_run.hpp because it names Verilator's headers, which only the RTL's users build with.
#pragma once

#include <cstddef>
#include <cstdint>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "hls/common/line_buffer.hpp"
#include "host/pipeline/stream_run.hpp"
#include "host/reference/line_buffer_ref.hpp"
#include "sim/core/components.hpp"
#include "sim/core/frame_beats.hpp"
#include "sim/models/pipeline_shell.hpp"
#include "sim/rtl/rtl_stream.hpp"

namespace scw::host::pipeline {

/// Streams `grey` o.frames times through the line buffer of `Params` (o.engine "rtl": the
/// Verilated `RtlTop`, else the C++ kernel), checks every beat against
/// reference::line_buffer_reference and notes each finished frame on `log`. Throws
/// std::runtime_error saying how many beats differ.
template <typename Params, typename RtlTop>
StreamRun stream_line_buffer(const StreamOptions& o, const cv::Mat& grey, std::ostream& log) {
  using Kernel = hls::LineBuffer<std::uint8_t, Params>;
  using In = typename Kernel::in_type;
  using Out = typename Kernel::out_type;
  constexpr int P = Params::kPpc;
  const int w = grey.cols, h = grey.rows;

  // Beats of one frame, and the expected windows by indexing the image directly.
  const cv::Mat img = grey.isContinuous() ? grey : grey.clone();
  const auto frame = sim::frame_beats<P>(img.ptr<std::uint8_t>(), w, h);
  const auto expect =
      reference::line_buffer_reference<P, Params::kRows>(img.ptr<std::uint8_t>(), w, h);
  std::vector<In> in;
  for (int f = 0; f < o.frames; ++f) in.insert(in.end(), frame.begin(), frame.end());

  sim::Simulator s;
  auto& f_in = s.fifo<In>("source_to_line_buffer", 4);
  auto& f_out = s.fifo<Out>("line_buffer_to_sink", 4);
  const auto stalls = sim::StallPattern::parse(o.stalls);
  auto& src = s.add<sim::Source<In>>("source", f_in, in, stalls);
  if (o.engine == "rtl") {
    using Rtl = sim::RtlStream<RtlTop, In, Out>;
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
          log << "  frame " << done_frames << "/" << o.frames << " done at cycle " << s.cycle()
              << "\n";
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
  return {s.report(),   P,         Params::kMaxWidthPx,  Params::kRows,        Params::kLatency,
          frame.size(), in.size(), sim::pack_all(frame), sim::pack_all(expect)};
}

}  // namespace scw::host::pipeline
