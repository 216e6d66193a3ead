// SPDX-License-Identifier: Apache-2.0
// The simulator clocks Verilated RTL and C++ twins side by side: any block swapped for its twin
// gives the same beats at the same cycles.
#include <catch2/catch.hpp>

#include "host/reference/line_buffer_ref.hpp"
#include "sim/core/components.hpp"
#include "sim/core/elastic.hpp"
#include "sim/models/pipeline_shell.hpp"
#include "sim/rtl/rtl_stream.hpp"
#include "tests/common/primitive_configs.hpp"
#include "Vline_buffer_p2.h"
#include "Vskid_buf.h"
#include "Vskid_buf_scw_skid_buf.h"

namespace {

using namespace scw;
using Params = test::LineBufP2;
using Kernel = hls::LineBuffer<std::uint8_t, Params>;
using In = Kernel::in_type;
using Out = Kernel::out_type;

struct ChainResult {
  std::vector<Out> out;
  sim::SimReport report;
};

/// source -> fifo -> line buffer -> fifo -> skid buffer -> fifo -> sink, with either block
/// as RTL or as its C++ twin.
template <typename LineBuf, typename Skid>
ChainResult run_chain(LineBuf lb, Skid skid, const std::vector<In>& in,
                      const sim::StallPattern& stalls) {
  sim::Simulator s;
  auto& f_in = s.fifo<In>("src_to_lb", 2);
  auto& f_mid = s.fifo<Out>("lb_to_skid", 3);
  auto& f_out = s.fifo<Out>("skid_to_sink", 2);
  auto& src = s.add<sim::Source<In>>("source", f_in, in, stalls);
  s.add<sim::StreamComponent<LineBuf>>("line_buffer", std::move(lb), f_in, f_mid);
  s.add<sim::StreamComponent<Skid>>("skid", std::move(skid), f_mid, f_out);
  auto& sink = s.add<sim::Sink<Out>>("sink", f_out, stalls);
  s.run_until([&] { return src.done() && sink.beats().size() == in.size(); }, 100000);
  return {sink.beats(), s.report()};
}

bool same_stamps(const sim::SimReport& a, const sim::SimReport& b) {
  if (a.stages.size() != b.stages.size()) return false;
  for (std::size_t i = 0; i < a.stages.size(); ++i) {
    const auto& fa = a.stages[i].frames;
    const auto& fb = b.stages[i].frames;
    if (fa.size() != fb.size()) return false;
    for (std::size_t k = 0; k < fa.size(); ++k)
      if (fa[k].first_in != fb[k].first_in || fa[k].last_in != fb[k].last_in ||
          fa[k].first_out != fb[k].first_out || fa[k].last_out != fb[k].last_out)
        return false;
  }
  return a.cycles == b.cycles;
}

}  // namespace

TEST_CASE("sim clocks RTL and C++ blocks in one chain", "[rtl][sim][pipeline]") {
  constexpr int W = Params::kMaxWidthPx;
  constexpr int H = 6;
  std::vector<In> in;
  std::vector<Out> expected;
  for (int f = 0; f < 3; ++f) {
    const auto img = test::random_image(W, H, 40 + static_cast<std::uint64_t>(f));
    const auto beats = scw::sim::frame_beats<Params::kPpc>(img.data(), W, H);
    const auto ref =
        scw::reference::line_buffer_reference<Params::kPpc, Params::kRows>(img.data(), W, H);
    in.insert(in.end(), beats.begin(), beats.end());
    expected.insert(expected.end(), ref.begin(), ref.end());
  }
  using CppLb = sim::PipelineShell<Kernel, Params::kLatency>;
  using RtlLb = sim::RtlStream<Vline_buffer_p2, In, Out>;
  using CppSkid = sim::SkidBuf<Out>;
  using RtlSkid = sim::RtlStream<Vskid_buf, Out, Out>;
  static_assert(Vskid_buf_scw_skid_buf::Width == sim::BeatLayout<Out>::kBits,
                "the skid buffer carries a whole packed line-buffer beat");

  for (const auto& stalls : sim::StallPattern::all(2)) {
    DYNAMIC_SECTION("stalls " << stalls.name()) {
      const auto all_cpp = run_chain(CppLb(), CppSkid(), in, stalls);
      const auto mixed = run_chain(RtlLb("line_buffer"), CppSkid(), in, stalls);
      const auto all_rtl = run_chain(RtlLb("line_buffer"), RtlSkid("skid"), in, stalls);
      CHECK(all_cpp.out == expected);
      CHECK(mixed.out == expected);
      CHECK(all_rtl.out == expected);
      CHECK(same_stamps(all_cpp.report, mixed.report));
      CHECK(same_stamps(all_cpp.report, all_rtl.report));
      // Three frames seen at every stage boundary, in order.
      for (const auto& st : mixed.report.stages) {
        if (st.name == "source" || st.name == "sink") continue;
        REQUIRE(st.frames.size() == 3);
        for (const auto& f : st.frames) {
          CHECK(f.first_in <= f.last_in);
          CHECK(f.first_out > f.first_in);
          CHECK(f.last_out > f.last_in);
        }
      }
    }
  }
}
