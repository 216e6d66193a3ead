// SPDX-License-Identifier: Apache-2.0
// [rtl] scw_frame_check against sim::FrameCheckModel: both driven with the same inputs every
// cycle and every output compared every cycle, under every stall pattern; flags against the
// expected sequence and a plain segment-by-segment reference; data unchanged; a full flag path
// stalls the input exactly at the frame-closing beat.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cstdint>
#include <functional>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "sim/core/components.hpp"
#include "sim/core/frame_beats.hpp"
#include "sim/core/side_component.hpp"
#include "sim/core/simulator.hpp"
#include "sim/core/stream_check.hpp"
#include "sim/models/frame_check_model.hpp"
#include "sim/rtl/frame_check_rtl.hpp"
#include "sim/rtl/rtl_params.hpp"
#include "tests/pipeline/frame_check_configs.hpp"
#include "Vframe_check_p1.h"
#include "Vframe_check_p1_scw_frame_check.h"
#include "Vframe_check_p2.h"
#include "Vframe_check_p2_scw_frame_check.h"

namespace {

using scw::hls::pipeline::FrameCheckConfig;
using scw::hls::pipeline::FrameFlag;
using scw::sim::StallGen;
using scw::sim::StallPattern;
using scw::test::pipeline::CheckP1;
using scw::test::pipeline::CheckP2;

// frame_check.cmake builds these two with -G.
static_assert(scw::sim::frame_check_params_match<Vframe_check_p1_scw_frame_check, CheckP1>());
static_assert(scw::sim::frame_check_params_match<Vframe_check_p2_scw_frame_check, CheckP2>());
static_assert(Vframe_check_p1_scw_frame_check::MaxWidthPx == 16 && CheckP1::kWidthBits == 5 &&
              CheckP1::kHeightBits == 4);

template <int P>
using Params = std::conditional_t<P == 1, CheckP1, CheckP2>;
template <int P>
using VCheck = scw::sim::ByPpc<P, Vframe_check_p1, Vframe_check_p2, Vframe_check_p2>;
template <int P>
using In = scw::hls::Beat<scw::hls::pixel_t, P>;
template <int P>
using Model = scw::sim::FrameCheckModel<P, Params<P>::kMaxWidthPx, Params<P>::kMaxHeight>;
template <int P>
using Rtl = scw::sim::FrameCheckRtl<VCheck<P>, Params<P>>;

/// One cycle at the ports (as the C++ model saw it; the RTL's are checked equal).
struct CycleLog {
  bool in_valid = false;
  bool in_ready = false;
  std::size_t offered = 0;  // index of the beat offered (when in_valid)
  bool out_ready = false;
  bool flag_valid = false;
  bool flag_ready = false;
};

template <int P>
struct TwinRun {
  std::vector<In<P>> out;
  std::vector<FrameFlag> flags;
  std::vector<CycleLog> log;
  std::vector<std::string> problems;  // C++ != RTL, or a handshake rule broken
  bool timed_out = false;
  std::int64_t cycles = 0;
  std::int64_t frames = 0, flagged = 0;  // the C++ kernel's counters
};

std::string describe(const In<1>& b) {
  std::ostringstream s;
  s << "{px0 " << int(b.px[0]) << " sof " << b.sof << " eol " << b.eol << "}";
  return s.str();
}
std::string describe(const In<2>& b) {
  std::ostringstream s;
  s << "{px " << int(b.px[0]) << "," << int(b.px[1]) << " sof " << b.sof << " eol " << b.eol
    << "}";
  return s.str();
}

/// Drives the C++ model and the RTL with the same inputs every cycle: the input from `beats`
/// when the pattern's input side allows (held until accepted), out_ready from its output side,
/// flag_ready from `flag_ready(cycle)`. Compares every output every cycle, checks that valids
/// and data ignore the readies and hold while stalled. Stops once every beat has passed, both
/// output registers are empty, or after `max_cycles`.
template <int P>
TwinRun<P> run_twins(const std::vector<In<P>>& beats, const FrameCheckConfig& cfg,
                     const StallPattern& pattern,
                     const std::function<bool(std::int64_t)>& flag_ready,
                     std::int64_t max_cycles = 20000) {
  Model<P> cpp(cfg);
  Rtl<P> rtl("frame_check", cfg);
  TwinRun<P> r;
  scw::sim::StreamDriver<In<P>> drv(beats, pattern);
  StallGen out_gen(pattern, StallGen::Side::kOutput);
  auto fail = [&](std::int64_t c, const std::string& what) {
    if (r.problems.size() < 10) r.problems.push_back("cycle " + std::to_string(c) + ": " + what);
  };
  bool out_stalled = false, flag_stalled = false;
  In<P> prev_out{};
  FrameFlag prev_flag{};
  for (std::int64_t c = 0; c < max_cycles; ++c) {
    const bool in_valid = drv.valid();
    const In<P> in = drv.data();
    const bool oready = out_gen.next();
    const bool fready = flag_ready(c);
    // Registered outputs: the same whatever the readies.
    const auto cl = cpp.eval(in_valid, in, false, false);
    const auto ch = cpp.eval(in_valid, in, true, true);
    const auto rl = rtl.eval(in_valid, in, false, false);
    const auto rh = rtl.eval(in_valid, in, true, true);
    if (cl.out_valid != ch.out_valid || cl.flag_valid != ch.flag_valid ||
        (cl.out_valid && cl.out != ch.out) || (cl.flag_valid && cl.flag != ch.flag))
      fail(c, "C++ outputs depend on a ready");
    if (rl.out_valid != rh.out_valid || rl.flag_valid != rh.flag_valid ||
        (rl.out_valid && rl.out != rh.out) || (rl.flag_valid && rl.flag != rh.flag))
      fail(c, "RTL outputs depend on a ready");
    const auto oc = cpp.eval(in_valid, in, oready, fready);
    const auto orr = rtl.eval(in_valid, in, oready, fready);
    if (oc.in_ready != orr.in_ready)
      fail(c, "in_ready C++ " + std::to_string(oc.in_ready) + " RTL " +
                  std::to_string(orr.in_ready));
    if (oc.out_valid != orr.out_valid || (oc.out_valid && oc.out != orr.out))
      fail(c, "out C++ " + std::to_string(oc.out_valid) + " " + describe(oc.out) + " RTL " +
                  std::to_string(orr.out_valid) + " " + describe(orr.out));
    if (oc.flag_valid != orr.flag_valid || (oc.flag_valid && oc.flag != orr.flag))
      fail(c, "flag C++ " + std::to_string(oc.flag_valid) + "/" + std::to_string(oc.flag.error) +
                  " RTL " + std::to_string(orr.flag_valid) + "/" +
                  std::to_string(orr.flag.error));
    if (out_stalled && (!oc.out_valid || oc.out != prev_out)) fail(c, "stalled out changed");
    if (flag_stalled && (!oc.flag_valid || oc.flag != prev_flag)) fail(c, "stalled flag changed");
    out_stalled = oc.out_valid && !oready;
    flag_stalled = oc.flag_valid && !fready;
    prev_out = oc.out;
    prev_flag = oc.flag;

    if (drv.done() && !oc.out_valid && !oc.flag_valid) {
      r.cycles = c;
      r.frames = cpp.kernel().frames();
      r.flagged = cpp.kernel().frames_flagged();
      return r;
    }
    r.log.push_back({in_valid, oc.in_ready, drv.sent(), oready, oc.flag_valid, fready});
    if (oc.out_valid && oready) r.out.push_back(oc.out);
    if (oc.flag_valid && fready) r.flags.push_back(oc.flag);
    cpp.tick();
    rtl.tick();
    drv.clock(in_valid && oc.in_ready);
  }
  r.timed_out = true;
  r.cycles = max_cycles;
  return r;
}

/// flag_ready follows the output side of `pattern` shifted by three cycles, so the two sinks
/// do not stall in step.
std::function<bool(std::int64_t)> flag_sink(const StallPattern& pattern) {
  StallPattern p = pattern;
  p.seed = pattern.seed + 77;
  auto gen = std::make_shared<StallGen>(p, StallGen::Side::kOutput);
  for (int i = 0; i < 3; ++i) gen->next();
  return [gen](std::int64_t) { return gen->next(); };
}

std::vector<bool> errors(const std::vector<FrameFlag>& flags) {
  std::vector<bool> v;
  for (const auto& f : flags) v.push_back(f.error);
  return v;
}

/// The plain reference, segment by segment: a frame is a sof beat and the beats up to
/// width/P * height in all or up to the next sof; its flag says error if a beat's eol is not
/// "last beat of its row", if it was cut short by a sof, or if beats without sof came since the
/// previous frame. A frame still open at the end has no flag yet.
template <int P>
std::vector<bool> reference_flags(const std::vector<In<P>>& beats, const FrameCheckConfig& cfg) {
  const std::size_t bpr = static_cast<std::size_t>(cfg.width / P);
  const std::size_t n = bpr * static_cast<std::size_t>(cfg.height);
  std::vector<bool> flags;
  bool stray = false;
  std::size_t i = 0;
  while (i < beats.size()) {
    if (!beats[i].sof) {
      stray = true;
      ++i;
      continue;
    }
    bool err = stray;
    stray = false;
    std::size_t k = 0;
    for (; k < n && i + k < beats.size(); ++k) {
      if (k > 0 && beats[i + k].sof) break;
      if (beats[i + k].eol != (k % bpr == bpr - 1)) err = true;
    }
    if (k == n) {
      flags.push_back(err);
    } else if (i + k < beats.size()) {
      flags.push_back(true);  // cut short by the sof at i + k
    }
    i += k;
  }
  return flags;
}

std::vector<std::uint8_t> random_image(int w, int h, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<std::uint8_t> v(static_cast<std::size_t>(w * h));
  for (auto& p : v) p = static_cast<std::uint8_t>(rng());
  return v;
}

template <int P>
std::vector<In<P>> good_frame(const FrameCheckConfig& cfg, std::uint64_t seed) {
  const auto img = random_image(cfg.width, cfg.height, seed);
  return scw::sim::frame_beats<P>(img.data(), cfg.width, cfg.height);
}

template <int P>
void append(std::vector<In<P>>& a, const std::vector<In<P>>& b) {
  a.insert(a.end(), b.begin(), b.end());
}

template <int P>
std::vector<In<P>> stray_beats(int n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<In<P>> v(static_cast<std::size_t>(n));
  for (auto& b : v) {
    for (auto& p : b.px) p = static_cast<std::uint8_t>(rng());
    b.eol = rng() % 2 == 0;
  }
  return v;
}

/// One broken-geometry case: the beats and the flags they must give.
template <int P>
struct Case {
  std::string name;
  std::vector<In<P>> beats;
  std::vector<bool> flags;
};

template <int P>
std::vector<Case<P>> cases(const FrameCheckConfig& cfg) {
  const int bpr = cfg.width / P;
  const auto row_end = [&](int row) { return static_cast<std::size_t>(row * bpr + bpr - 1); };
  std::vector<Case<P>> v;
  std::uint64_t seed = 1000;
  auto good = [&] { return good_frame<P>(cfg, seed++); };
  auto then_good = [&](std::vector<In<P>> bad, int n) {
    for (int i = 0; i < n; ++i) append(bad, good());
    return bad;
  };

  v.push_back({"good frames back to back", then_good({}, 3), {false, false, false}});
  {
    // Row 2 loses its last beat; eol comes one beat early. The frame is one beat short by
    // count, so the next sof closes it (error) and the next frame starts clean.
    auto bad = good();
    bad[row_end(2) - 1].eol = true;
    bad.erase(bad.begin() + static_cast<long>(row_end(2)));
    v.push_back({"a short row (early eol)", then_good(bad, 2), {true, false, false}});
  }
  {
    auto bad = good();
    bad[row_end(1)].eol = false;
    v.push_back({"a missing eol (row of the right length)", then_good(bad, 2),
                 {true, false, false}});
  }
  {
    // Row 2 gets an extra beat carrying the eol: the count closes the frame one beat before its
    // end (error), and the beat left over is stray, so the next frame is flagged too.
    auto bad = good();
    bad[row_end(2)].eol = false;
    In<P> extra = bad[row_end(2)];
    extra.eol = true;
    extra.px[0] = 0x5a;
    bad.insert(bad.begin() + static_cast<long>(row_end(2)) + 1, extra);
    v.push_back({"a long row (missing eol, one beat too many)", then_good(bad, 2),
                 {true, true, false}});
  }
  {
    auto bad = good();
    bad.resize(bad.size() - static_cast<std::size_t>(bpr + 2));
    v.push_back({"a frame cut short by a sof mid-frame", then_good(bad, 2), {true, false, false}});
  }
  {
    auto bad = good();
    bad.resize(1);  // a frame of one beat: the next beat is a sof
    v.push_back({"a frame cut short after its sof beat", then_good(bad, 1), {true, false}});
  }
  v.push_back({"stray beats before a sof", then_good(stray_beats<P>(3, seed++), 2),
               {true, false}});
  {
    auto s = good();
    append(s, stray_beats<P>(2, seed++));
    v.push_back({"stray beats between frames", then_good(s, 2), {false, true, false}});
  }
  {
    auto bad = good();
    bad[static_cast<std::size_t>(3 * bpr + 1)].eol = true;  // row 3, beat 1
    v.push_back({"eol on a wrong beat", then_good(bad, 2), {true, false, false}});
  }
  {
    auto bad = good();
    bad.back().eol = false;  // the closing beat itself is wrong: its own flag says so
    v.push_back({"the frame-closing beat without eol", then_good(bad, 1), {true, false}});
  }
  return v;
}

template <int P>
void check_cases(const FrameCheckConfig& cfg) {
  for (const auto& k : cases<P>(cfg)) {
    REQUIRE(reference_flags<P>(k.beats, cfg) == k.flags);  // the reference agrees
    for (const auto& pattern : StallPattern::all(3)) {
      INFO(k.name << ", stalls " << pattern.name());
      const auto r = run_twins<P>(k.beats, cfg, pattern, flag_sink(pattern));
      INFO((r.problems.empty() ? std::string() : r.problems.front()));
      CHECK(r.problems.empty());
      REQUIRE_FALSE(r.timed_out);
      CHECK(r.out == k.beats);  // data passes unchanged
      CHECK(errors(r.flags) == k.flags);
      CHECK(r.frames == static_cast<std::int64_t>(k.flags.size()));
      CHECK(r.flagged ==
            static_cast<std::int64_t>(std::count(k.flags.begin(), k.flags.end(), true)));
    }
  }
}

/// Random damage (dropped, repeated and stray beats, flipped flags) to a stream of good frames.
template <int P>
std::vector<In<P>> damaged_stream(const FrameCheckConfig& cfg, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<In<P>> good;
  for (int f = 0; f < 6; ++f) append(good, good_frame<P>(cfg, seed * 10 + f));
  std::vector<In<P>> v;
  for (const auto& b : good) {
    const auto r = rng() % 100;
    if (r < 3) continue;  // dropped
    In<P> c = b;
    if (r < 6) c.eol = !c.eol;
    if (r == 6) c.sof = !c.sof;
    v.push_back(c);
    if (r == 7 || r == 8) v.push_back(c);  // repeated
    if (r == 9) append(v, stray_beats<P>(2, rng()));
  }
  append(v, good_frame<P>(cfg, seed * 10 + 9));  // closes whatever is open
  return v;
}

template <int P>
void check_random(const FrameCheckConfig& cfg) {
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    const auto beats = damaged_stream<P>(cfg, seed);
    const auto expected = reference_flags<P>(beats, cfg);
    for (const auto& pattern : {StallPattern{}, StallPattern::parse("both"),
                                StallPattern::parse("random:" + std::to_string(seed))}) {
      INFO("seed " << seed << ", stalls " << pattern.name());
      const auto r = run_twins<P>(beats, cfg, pattern, flag_sink(pattern));
      INFO((r.problems.empty() ? std::string() : r.problems.front()));
      CHECK(r.problems.empty());
      REQUIRE_FALSE(r.timed_out);
      CHECK(r.out == beats);
      CHECK(errors(r.flags) == expected);
    }
  }
}

/// The flag sink refuses until cycle `open_at`; the input is always offered and the output
/// always taken. The first frame's flag fills the register; the second frame flows until the
/// beat that would emit its flag (`blocked`), which waits exactly until the flag is read.
template <int P>
void check_flag_backpressure(const std::vector<In<P>>& beats, const FrameCheckConfig& cfg,
                             std::size_t blocked, const std::vector<bool>& flags) {
  const std::int64_t open_at = 300;
  const auto r = run_twins<P>(beats, cfg, StallPattern{},
                              [open_at](std::int64_t c) { return c >= open_at; });
  INFO((r.problems.empty() ? std::string() : r.problems.front()));
  CHECK(r.problems.empty());
  REQUIRE_FALSE(r.timed_out);
  REQUIRE(r.log.size() > static_cast<std::size_t>(open_at));
  for (std::int64_t c = 0; c < open_at; ++c) {
    const auto& l = r.log[static_cast<std::size_t>(c)];
    INFO("cycle " << c << " offers beat " << l.offered);
    REQUIRE(l.in_valid);
    // Refused exactly when the flag-emitting beat is offered while the flag register is full.
    CHECK(l.in_ready == (l.offered != blocked));
  }
  // The stall held on that beat from the cycle it was offered until the sink opened.
  CHECK(r.log[static_cast<std::size_t>(open_at) - 1].offered == blocked);
  CHECK(r.log[static_cast<std::size_t>(open_at)].in_ready);  // taken as the flag is read
  CHECK(r.log[static_cast<std::size_t>(open_at)].offered == blocked);
  // Nothing lost.
  CHECK(r.out == beats);
  CHECK(errors(r.flags) == flags);
}

/// Both models inside the cycle simulator (SideComponent between FIFOs), as the pipeline
/// chain uses them: the same beats and flags come out.
template <int P, typename M>
std::pair<std::vector<In<P>>, std::vector<scw::hls::Packet<FrameFlag>>> run_component(
    M model, const std::vector<In<P>>& beats, std::size_t n_flags, const StallPattern& p) {
  using Flag = scw::hls::Packet<FrameFlag>;
  scw::sim::Simulator s;
  auto& in = s.fifo<In<P>>("raw", 2);
  auto& out = s.fifo<In<P>>("checked", 2);
  auto& flags = s.fifo<Flag>("flags", 1);
  auto& src = s.add<scw::sim::Source<In<P>>>("source", in, beats, p);
  s.add<scw::sim::SideComponent<M>>("check", std::move(model), in, out, flags);
  auto& sink = s.add<scw::sim::Sink<In<P>>>("sink", out, p);
  auto& fsink = s.add<scw::sim::Sink<Flag>>("flag_sink", flags, StallPattern::parse("both"));
  s.run_until(
      [&] { return src.done() && sink.beats().size() == beats.size() &&
                   fsink.beats().size() == n_flags; },
      100000);
  return {sink.beats(), fsink.beats()};
}

}  // namespace

TEST_CASE("scw_frame_check equals the model on every geometry case, flags as expected",
          "[pipeline][rtl][frame_check]") {
  SECTION("P = 1, 12 x 5") { check_cases<1>({12, 5}); }
  SECTION("P = 2, 12 x 5") { check_cases<2>({12, 5}); }
  SECTION("P = 2, full 16 x 8") { check_cases<2>({16, 8}); }
  SECTION("P = 1, rows of one beat (1 x 6)") {
    // Every beat ends its row: eol on every beat.
    const FrameCheckConfig cfg{1, 6};
    std::vector<In<1>> beats;
    for (int f = 0; f < 3; ++f) append(beats, good_frame<1>(cfg, 50 + f));
    beats[8].eol = false;  // frame 1, row 2
    for (const auto& pattern : StallPattern::all(3)) {
      INFO("stalls " << pattern.name());
      const auto r = run_twins<1>(beats, cfg, pattern, flag_sink(pattern));
      CHECK(r.problems.empty());
      CHECK(r.out == beats);
      CHECK(errors(r.flags) == std::vector<bool>{false, true, false});
    }
  }
}

TEST_CASE("scw_frame_check equals the model on randomly damaged streams",
          "[pipeline][rtl][frame_check]") {
  SECTION("P = 1") { check_random<1>({12, 5}); }
  SECTION("P = 2") { check_random<2>({8, 4}); }
}

TEST_CASE("scw_frame_check: a full flag path stalls the input at the frame-closing beat",
          "[pipeline][rtl][frame_check]") {
  const FrameCheckConfig cfg{12, 5};
  SECTION("P = 2, the closing beat of the second frame waits") {
    std::vector<In<2>> beats;
    for (int f = 0; f < 3; ++f) append(beats, good_frame<2>(cfg, 70 + f));
    const std::size_t n = beats.size() / 3;
    check_flag_backpressure<2>(beats, cfg, 2 * n - 1, {false, false, false});
  }
  SECTION("P = 1, the sof that cuts the second frame short waits") {
    std::vector<In<1>> beats = good_frame<1>(cfg, 80);
    const std::size_t n = beats.size();
    auto cut = good_frame<1>(cfg, 81);
    cut.resize(n - 7);
    append(beats, cut);
    append(beats, good_frame<1>(cfg, 82));
    check_flag_backpressure<1>(beats, cfg, 2 * n - 7, {false, true, false});
  }
}

TEST_CASE("scw_frame_check passes one beat per clock with one register of latency",
          "[pipeline][rtl][frame_check][throughput]") {
  const FrameCheckConfig cfg{16, 8};
  std::vector<In<2>> beats;
  for (int f = 0; f < 4; ++f) append(beats, good_frame<2>(cfg, 90 + f));
  const auto r = run_twins<2>(beats, cfg, StallPattern{}, [](std::int64_t) { return true; });
  CHECK(r.problems.empty());
  // Beat i is taken in cycle i and presented in cycle i + 1 (Latency = 1).
  CHECK(r.cycles == static_cast<std::int64_t>(beats.size()) + CheckP2::kLatency);
  for (const auto& l : r.log) CHECK((!l.in_valid || l.in_ready));
  CHECK(errors(r.flags) == std::vector<bool>(4, false));
}

TEST_CASE("SideComponent runs either frame check model between FIFOs with the same result",
          "[pipeline][rtl][frame_check][sim]") {
  const FrameCheckConfig cfg{12, 5};
  const auto k = cases<2>(cfg)[4];  // a frame cut short, then two good frames
  for (const auto& pattern : {StallPattern{}, StallPattern::parse("random:5")}) {
    INFO("stalls " << pattern.name());
    const auto c = run_component<2>(Model<2>(cfg), k.beats, k.flags.size(), pattern);
    const auto v = run_component<2>(Rtl<2>("frame_check_component", cfg), k.beats,
                                    k.flags.size(), pattern);
    CHECK(c.first == k.beats);
    CHECK(v.first == k.beats);
    REQUIRE(c.second.size() == k.flags.size());
    CHECK(c.second == v.second);
    for (std::size_t i = 0; i < k.flags.size(); ++i) {
      CHECK(c.second[i].data.error == k.flags[i]);
      CHECK(c.second[i].last);
    }
  }
}

TEST_CASE("frame check configurations outside the build are refused",
          "[pipeline][frame_check]") {
  using scw::hls::pipeline::check_frame_check_config;
  CHECK_NOTHROW(check_frame_check_config<CheckP2>({16, 8}));
  CHECK_THROWS_AS(check_frame_check_config<CheckP2>({18, 8}), std::invalid_argument);
  CHECK_THROWS_AS(check_frame_check_config<CheckP2>({7, 8}), std::invalid_argument);
  CHECK_THROWS_AS(check_frame_check_config<CheckP2>({16, 9}), std::invalid_argument);
  CHECK_THROWS_AS(check_frame_check_config<CheckP2>({16, 0}), std::invalid_argument);
  CHECK_THROWS_AS(check_frame_check_config<CheckP2>({2, 1}), std::invalid_argument);
  CHECK_NOTHROW(check_frame_check_config<CheckP1>({1, 2}));
}
