// SPDX-License-Identifier: Apache-2.0
// RTL primitives against their C++ twins: the same cycle trace under every stall pattern,
// handshake rules checked every cycle, and the data against an independent expectation.
#include <unistd.h>

#include <catch2/catch.hpp>
#include <filesystem>

#include "host/reference/line_buffer_ref.hpp"
#include "sim/core/elastic.hpp"
#include "sim/core/stream_check.hpp"
#include "sim/models/pipeline_shell.hpp"
#include "sim/rtl/rtl_params.hpp"
#include "sim/rtl/rtl_stream.hpp"
#include "tests/common/primitive_configs.hpp"
#include "tests/common/scoped_env.hpp"
#include "tests/common/twin_check.hpp"
#include "Vfifo_d1.h"
#include "Vfifo_d1_scw_fifo.h"
#include "Vfifo_d1r.h"
#include "Vfifo_d1r_scw_fifo.h"
#include "Vfifo_d2.h"
#include "Vfifo_d2_scw_fifo.h"
#include "Vfifo_d2r.h"
#include "Vfifo_d2r_scw_fifo.h"
#include "Vfifo_d5.h"
#include "Vfifo_d5_scw_fifo.h"
#include "Vfifo_d5r.h"
#include "Vfifo_d5r_scw_fifo.h"
#include "Vline_buffer_p1.h"
#include "Vline_buffer_p1_scw_line_buffer.h"
#include "Vline_buffer_p2.h"
#include "Vline_buffer_p2_scw_line_buffer.h"
#include "Vline_buffer_p4.h"
#include "Vline_buffer_p4_scw_line_buffer.h"
#include "Vskid_buf.h"
#include "Vskid_buf_scw_skid_buf.h"
#include "Vstream_reg.h"
#include "Vstream_reg_scw_stream_reg.h"

namespace {

using namespace scw;
using test::Beat2;
using test::Beat4;

// The Verilated parameters must be the C++ ones (tests/CMakeLists.txt passes them with -G).
static_assert(Vfifo_d1_scw_fifo::Depth == test::FifoD1::kDepth &&
              Vfifo_d1_scw_fifo::Width == test::FifoD1::kWidth);
static_assert(Vfifo_d2_scw_fifo::Depth == test::FifoD2::kDepth &&
              Vfifo_d2_scw_fifo::Width == test::FifoD2::kWidth);
static_assert(Vfifo_d5_scw_fifo::Depth == test::FifoD5::kDepth &&
              Vfifo_d5_scw_fifo::Width == test::FifoD5::kWidth);
static_assert(Vfifo_d1r_scw_fifo::Depth == test::FifoD1::kDepth &&
              Vfifo_d1r_scw_fifo::Width == test::FifoD1::kWidth && Vfifo_d1r_scw_fifo::OutReg);
static_assert(Vfifo_d2r_scw_fifo::Depth == test::FifoD2::kDepth &&
              Vfifo_d2r_scw_fifo::Width == test::FifoD2::kWidth && Vfifo_d2r_scw_fifo::OutReg);
static_assert(Vfifo_d5r_scw_fifo::Depth == test::FifoD5::kDepth &&
              Vfifo_d5r_scw_fifo::Width == test::FifoD5::kWidth && Vfifo_d5r_scw_fifo::OutReg);
static_assert(Vstream_reg_scw_stream_reg::Width == test::kElasticWidth);
static_assert(Vskid_buf_scw_skid_buf::Width == test::kElasticWidth);

static_assert(sim::line_buffer_params_match<Vline_buffer_p1_scw_line_buffer, test::LineBufP1>());
static_assert(sim::line_buffer_params_match<Vline_buffer_p2_scw_line_buffer, test::LineBufP2>());
static_assert(sim::line_buffer_params_match<Vline_buffer_p4_scw_line_buffer, test::LineBufP4>());

/// Runs the twin and the RTL under every stall pattern; both must follow the handshake rules,
/// produce `expected`, and agree cycle by cycle.
template <typename MakeCpp, typename MakeRtl, typename In, typename Out>
void check_twins(MakeCpp make_cpp, MakeRtl make_rtl, const std::vector<In>& in,
                 const std::vector<Out>& expected) {
  for (const auto& pattern : sim::StallPattern::all(3)) {
    DYNAMIC_SECTION("stalls " << pattern.name()) {
      auto cpp = make_cpp();
      auto rtl = make_rtl();
      const auto rc = sim::run_stream(cpp, in, pattern, expected.size());
      const auto rr = sim::run_stream(rtl, in, pattern, expected.size());
      test::check_twin_runs(rc, rr);
      CHECK(rc.out == expected);
    }
  }
}

template <typename VM, typename B>
void check_fifo(int depth) {
  const auto in = test::random_beats<B>(400, 11);
  check_twins([&] { return sim::FifoModel<B>("fifo", depth); },
              [] { return sim::RtlStream<VM, B, B>("fifo"); }, in, in);
}

}  // namespace

TEST_CASE("scw_fifo equals sim::Fifo cycle for cycle", "[rtl][fifo]") {
  SECTION("depth 1") { check_fifo<Vfifo_d1, Beat2>(test::FifoD1::kDepth); }
  SECTION("depth 2") { check_fifo<Vfifo_d2, Beat2>(test::FifoD2::kDepth); }
  SECTION("depth 5") { check_fifo<Vfifo_d5, Beat4>(test::FifoD5::kDepth); }
  SECTION("depth 1, registered output") { check_fifo<Vfifo_d1r, Beat2>(test::FifoD1::kDepth); }
  SECTION("depth 2, registered output") { check_fifo<Vfifo_d2r, Beat2>(test::FifoD2::kDepth); }
  SECTION("depth 5, registered output") { check_fifo<Vfifo_d5r, Beat4>(test::FifoD5::kDepth); }
}

TEST_CASE("scw_stream_reg equals sim::StreamReg cycle for cycle", "[rtl][stream_reg]") {
  const auto in = test::random_beats<Beat4>(400, 12);
  check_twins([] { return sim::StreamReg<Beat4>(); },
              [] { return sim::RtlStream<Vstream_reg, Beat4, Beat4>("stream_reg"); }, in, in);
}

TEST_CASE("scw_skid_buf equals sim::SkidBuf cycle for cycle", "[rtl][skid_buf]") {
  const auto in = test::random_beats<Beat4>(400, 13);
  check_twins([] { return sim::SkidBuf<Beat4>(); },
              [] { return sim::RtlStream<Vskid_buf, Beat4, Beat4>("skid_buf"); }, in, in);
}

TEST_CASE("elastic blocks move one beat per clock without stalls", "[rtl][throughput]") {
  // Exact cycle counts, not time: N beats through a one-register block take N + 1 cycles.
  const auto in = test::random_beats<Beat4>(100, 14);
  const sim::StallPattern none{};
  sim::RtlStream<Vfifo_d5, Beat4, Beat4> fifo("fifo");
  sim::RtlStream<Vstream_reg, Beat4, Beat4> reg("reg");
  sim::RtlStream<Vskid_buf, Beat4, Beat4> skid("skid");
  CHECK(sim::run_stream(fifo, in, none, in.size()).cycles == 101);
  CHECK(sim::run_stream(reg, in, none, in.size()).cycles == 101);
  CHECK(sim::run_stream(skid, in, none, in.size()).cycles == 101);
}

namespace {

template <typename VM, typename Params>
void check_line_buffer() {
  using Kernel = hls::LineBuffer<std::uint8_t, Params>;
  using Shell = sim::PipelineShell<Kernel, Params::kLatency>;
  using In = typename Kernel::in_type;
  using Out = typename Kernel::out_type;
  constexpr int P = Params::kPpc;
  // Frames back to back: full width, narrower (rows set by eol), rows of one beat (each beat
  // reads the RAM word the previous beat is writing), full width again.
  std::vector<In> in;
  std::vector<Out> expected;
  const int sizes[][2] = {
      {Params::kMaxWidthPx, 7}, {Params::kMaxWidthPx / 2, 5}, {P, 6}, {Params::kMaxWidthPx, 4}};
  std::uint64_t seed = 21;
  for (const auto& wh : sizes) {
    const auto img = test::random_image(wh[0], wh[1], seed++);
    const auto beats = scw::sim::frame_beats<P>(img.data(), wh[0], wh[1]);
    in.insert(in.end(), beats.begin(), beats.end());
    const auto ref =
        scw::reference::line_buffer_reference<P, Params::kRows>(img.data(), wh[0], wh[1]);
    expected.insert(expected.end(), ref.begin(), ref.end());
  }
  check_twins([] { return Shell(); }, [] { return sim::RtlStream<VM, In, Out>("line_buffer"); }, in,
              expected);
}

}  // namespace

TEST_CASE("scw_line_buffer equals hls::LineBuffer beat for beat", "[rtl][line_buffer]") {
  SECTION("P = 1, 3 rows") { check_line_buffer<Vline_buffer_p1, test::LineBufP1>(); }
  SECTION("P = 2, 2 rows") { check_line_buffer<Vline_buffer_p2, test::LineBufP2>(); }
  SECTION("P = 4, 3 rows") { check_line_buffer<Vline_buffer_p4, test::LineBufP4>(); }
}

TEST_CASE("scw_line_buffer flags malformed rows and recovers on the next sof",
          "[rtl][line_buffer][malformed]") {
  using Params = test::LineBufP2;
  using Kernel = hls::LineBuffer<std::uint8_t, Params>;
  using In = Kernel::in_type;
  using Out = Kernel::out_type;
  constexpr int P = Params::kPpc;
  constexpr int W = Params::kMaxWidthPx;

  auto good = test::random_image(W, 4, 31);
  const auto good_beats = scw::sim::frame_beats<P>(good.data(), W, 4);
  const auto good_ref = scw::reference::line_buffer_reference<P, Params::kRows>(good.data(), W, 4);

  std::vector<In> bad;
  SECTION("a row longer than MaxWidthPx") {
    const auto img = test::random_image(W + 2 * P, 3, 32);
    bad = sim::frame_beats<P>(img.data(), W + 2 * P, 3);
  }
  SECTION("a frame cut short mid-row (sof before eol)") {
    const auto img = test::random_image(W, 3, 33);
    bad = sim::frame_beats<P>(img.data(), W, 3);
    bad.resize(bad.size() - 3);
  }
  std::vector<In> in = bad;
  in.insert(in.end(), good_beats.begin(), good_beats.end());

  sim::PipelineShell<Kernel, Params::kLatency> cpp;
  sim::RtlStream<Vline_buffer_p2, In, Out> rtl("line_buffer");
  const auto rc = sim::run_stream(cpp, in, {}, in.size());
  const auto rr = sim::run_stream(rtl, in, {}, in.size());
  test::check_twin_runs(rc, rr);
  CHECK(cpp.kernel().error());
  CHECK(rtl.dut().err_o == 1);
  // The good frame after the bad one comes out exactly as the reference says.
  const std::vector<Out> tail(rr.out.end() - static_cast<long>(good_ref.size()), rr.out.end());
  CHECK(tail == good_ref);
}

TEST_CASE("SCW_FST_DIR switches FST tracing on", "[rtl][harness]") {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("scw_fst_" + std::to_string(static_cast<long>(::getpid())));
  std::filesystem::remove_all(dir);
  {
    scw::test::ScopedEnv fst("SCW_FST_DIR", dir.string());
    sim::Harness<Vstream_reg> h("traced_reg");
    h.reset();
    for (int i = 0; i < 10; ++i) h.tick();
  }
  {
    sim::Harness<Vstream_reg> h("untraced_reg");
    h.tick();
  }
  const auto fst = dir / "traced_reg.fst";
  REQUIRE(std::filesystem::exists(fst));
  CHECK(std::filesystem::file_size(fst) > 0);
  CHECK_FALSE(std::filesystem::exists(dir / "untraced_reg.fst"));
  std::filesystem::remove_all(dir);
}
