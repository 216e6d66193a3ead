// SPDX-License-Identifier: Apache-2.0
// [hls] The warning kernel: frame results equal a plain fold of the per-object arithmetic, the
// latency is kLatency clocks, stalls change nothing, broken tables are flagged and recovered.
#include <catch2/catch.hpp>

#include <random>
#include <vector>

#include "hls/warning/warning.hpp"
#include "host/vectors/warning_tables.hpp"
#include "host/warning/run_model.hpp"
#include "host/warning/setup.hpp"
#include "sim/core/stall.hpp"
#include "sim/core/stream_check.hpp"
#include "sim/models/warning_model.hpp"

namespace {

using scw::hls::labelling::FrameStatus;
using scw::hls::labelling::LabelPacket;
using scw::hls::warning::FrameResult;
using scw::hls::warning::Severity;
using scw::sim::StallPattern;
using scw::fixtures::fold_table;
using scw::fixtures::random_table;
using Params = scw::hls::warning::WarningParams<128>;

FrameStatus ok_status(std::size_t n) {
  FrameStatus s;
  s.objects = static_cast<std::uint32_t>(n);
  return s;
}

/// Frames back to back through the model under `pattern`.
std::vector<FrameResult> run_frames(const std::vector<LabelPacket>& words,
                                    const scw::hls::warning::WarningConfig& cfg,
                                    const StallPattern& pattern, std::size_t frames) {
  scw::sim::WarningModel<Params> m(cfg);
  const auto r = scw::sim::run_stream(m, words, pattern, frames, 100'000);
  REQUIRE(r.violations.empty());
  REQUIRE_FALSE(r.timed_out);
  std::vector<FrameResult> out;
  for (const auto& p : r.out) {
    CHECK(p.last);
    out.push_back(p.data);
  }
  return out;
}

/// `frames` random object tables back to back (every `empty_every`-th empty, the others of 1 ..
/// `max_objects` objects on a `width` x 480 image): their words, and each frame's result by a
/// plain fold of evaluate().
struct Frames {
  std::vector<LabelPacket> words;
  std::vector<FrameResult> expected;
};
Frames random_frames(std::mt19937& rng, const scw::host::warning::WarningSetup& setup,
                     const scw::hls::warning::WarningConfig& cfg, int frames, int empty_every,
                     int max_objects, int width) {
  Frames out;
  for (int f = 0; f < frames; ++f) {
    const int n = f % empty_every == 0 ? 0 : 1 + static_cast<int>(rng() % max_objects);
    const auto t = random_table(rng, setup, n, width, 480);
    const auto w = scw::warning::table_words(t, ok_status(t.size()));
    out.words.insert(out.words.end(), w.begin(), w.end());
    out.expected.push_back(fold_table<Params>(t, cfg));
  }
  return out;
}

}  // namespace

TEST_CASE("warning model: frame results equal a plain fold of evaluate() under every stall",
          "[hls]") {
  for (const auto& setup : {scw::fixtures::karlsruhe_setup(), scw::fixtures::thesis_setup()}) {
    const auto cfg = scw::host::warning::to_fixed(setup);
    std::mt19937 rng(1234);
    const auto [words, expected] = random_frames(rng, setup, cfg, 40, 7, 30, 1344);
    int severities[4] = {0, 0, 0, 0};
    for (const auto& e : expected) ++severities[static_cast<int>(e.severity)];
    INFO("frames by severity none/low/medium/high: " << severities[0] << "/" << severities[1]
                                                     << "/" << severities[2] << "/"
                                                     << severities[3]);
    CHECK(severities[0] > 0);  // the tables reach every outcome
    CHECK(severities[1] > 0);
    CHECK(severities[2] > 0);
    CHECK(severities[3] > 0);
    for (const auto& pattern : StallPattern::all(3)) {
      INFO("stalls " << pattern.name());
      CHECK(run_frames(words, cfg, pattern, expected.size()) == expected);
    }
  }
}

TEST_CASE("the frame function (the HLS top) equals the cycle model", "[hls]") {
  const auto setup = scw::fixtures::thesis_setup();
  const auto cfg = scw::host::warning::to_fixed(setup);
  std::mt19937 rng(77);
  const auto [words, expected] = random_frames(rng, setup, cfg, 12, 5, 20, 1280);
  scw::hls::warning::Warning<Params> k(cfg);
  std::vector<scw::hls::warning::ResultPacket> out(words.size());
  const int n = scw::hls::warning::warning_frame(k, words.data(), static_cast<int>(words.size()),
                                                 out.data());
  REQUIRE(n == static_cast<int>(expected.size()));
  std::vector<FrameResult> got;
  for (int i = 0; i < n; ++i) {
    CHECK(out[static_cast<std::size_t>(i)].last);
    got.push_back(out[static_cast<std::size_t>(i)].data);
  }
  CHECK(got == expected);
  CHECK(got == run_frames(words, cfg, StallPattern{}, expected.size()));
}

TEST_CASE("warning model: the result shows kLatency clocks after the status word is taken",
          "[hls]") {
  const auto setup = scw::fixtures::thesis_setup();
  const auto cfg = scw::host::warning::to_fixed(setup);
  for (int n : {0, 1, 5, 40}) {
    std::mt19937 rng(static_cast<unsigned>(n));
    const auto t = random_table(rng, setup, n, 1280, 480);
    std::int64_t cycles = 0;
    const auto r = scw::warning::run_warning(scw::warning::table_words(t, ok_status(t.size())),
                                             cfg, &cycles);
    CHECK(cycles == n + scw::hls::warning::kLatency);
    CHECK(r == fold_table<scw::warning::HostParams>(t, cfg));
  }
}

TEST_CASE("warning model: a result waiting for the sink holds the stage, then the next frame",
          "[hls]") {
  const auto setup = scw::fixtures::thesis_setup();
  const auto cfg = scw::host::warning::to_fixed(setup);
  scw::hls::warning::Warning<Params> k(cfg);
  const auto w = scw::warning::table_words({scw::fixtures::place_box(setup, 0.0, 8.0, 0.6, 1.8)},
                                           ok_status(1));
  std::size_t next = 0;
  for (int t = 0; t < 200; ++t) {  // the sink never takes
    const bool valid = next < w.size();
    if (valid && k.in_ready(false)) ++next;
    k.clock(valid, valid ? w[next - (k.in_ready(false) ? 1 : 0)] : LabelPacket{}, false);
  }
  REQUIRE(k.out_valid());
  CHECK(k.out().data.severity == Severity::kHigh);
  CHECK_FALSE(k.in_ready(false));  // one pipeline enable: nothing moves while the result waits
  CHECK(k.in_ready(true));
}

TEST_CASE("warning model: broken tables are flagged and the next frame is right", "[hls]") {
  const auto setup = scw::fixtures::karlsruhe_setup();
  const auto cfg = scw::host::warning::to_fixed(setup);
  const auto obj = scw::fixtures::place_box(setup, 0.0, 8.0, 0.6, 1.8);
  const std::vector<scw::hls::labelling::Object> good{obj};
  const FrameResult good_result = fold_table<Params>(good, cfg);
  REQUIRE(good_result.severity == Severity::kHigh);

  std::vector<LabelPacket> broken;
  SECTION("a status word without last") {
    broken = scw::warning::table_words(good, ok_status(1));
    broken.back().last = false;
  }
  SECTION("last on an object word, no status word") {
    broken = scw::warning::table_words(good, ok_status(1));
    broken.pop_back();
    broken.back().last = true;
  }
  SECTION("a status word counting other than the objects sent") {
    broken = scw::warning::table_words(good, ok_status(3));
  }
  SECTION("the labelling stage's own flags") {
    FrameStatus s = ok_status(1);
    s.stream_error = true;
    s.tile_overflow = true;
    s.object_overflow = true;
    broken = scw::warning::table_words(good, s);
  }
  auto words = broken;
  const auto next = scw::warning::table_words(good, ok_status(1));
  words.insert(words.end(), next.begin(), next.end());
  for (const auto& pattern : StallPattern::all(2)) {
    INFO("stalls " << pattern.name());
    const auto out = run_frames(words, cfg, pattern, 2);
    REQUIRE(out.size() == 2);
    CHECK(out[0].stream_error);
    CHECK(out[0].severity == Severity::kHigh);  // the objects that came are still judged
    CHECK(out[1] == good_result);
  }
}

TEST_CASE("warning model: flags carried, nothing measurable gives none", "[hls]") {
  const auto setup = scw::fixtures::karlsruhe_setup();
  const auto cfg = scw::host::warning::to_fixed(setup);
  FrameStatus s = ok_status(2);
  s.tile_overflow = true;
  scw::hls::labelling::Object far = scw::fixtures::place_box(setup, 0.0, 8.0, 0.6, 1.8);
  far.d_max = 15;  // below 1 px: too far to place
  scw::hls::labelling::Object low = scw::fixtures::place_box(setup, 0.0, 8.0, 1.5, 0.2);  // a marking
  const auto r = scw::warning::run_warning(scw::warning::table_words({far, low}, s), cfg);
  CHECK(r.tile_overflow);
  CHECK_FALSE(r.object_overflow);
  CHECK_FALSE(r.stream_error);
  CHECK(r.objects == 2);
  CHECK(r.obstacles == 0);
  CHECK(r.severity == Severity::kNone);
  CHECK(r.index == 0xffff);
}

TEST_CASE("warning model: an object at the top of the search range is judged at the bumper",
          "[hls]") {
  const auto setup = scw::fixtures::thesis_setup();  // d_limit 64 px: nearer than 9.4 m is unmeasured
  const auto cfg = scw::host::warning::to_fixed(setup);
  // Beside the tunnel, near it, at the limit: medium (judged at 0 m), while the same object
  // 30 m away in the tunnel is low; the near one decides and its distance is an upper bound.
  auto near = scw::fixtures::place_box(setup, 2.0, 9.0, 0.6, 1.8);
  near.d_max = static_cast<std::uint16_t>(16 * 64);
  const auto far = scw::fixtures::place_box(setup, -0.3, 30.0, 0.6, 1.8);
  const auto e = scw::warning::evaluate_object(near, cfg);
  REQUIRE(e.too_close);
  const auto r = scw::warning::run_warning(scw::warning::table_words({far, near}, ok_status(2)),
                                           cfg);
  CHECK(r.index == 1);
  CHECK(r.too_close);
  CHECK(r.severity == Severity::kMedium);
  CHECK(r.distance_mm == e.distance_mm);
  CHECK(r.distance_mm >= 9000 - 1650);  // the bound the range allows, never farther than that
  // Past the table: still too close, never wrapped round to a far distance.
  near.d_max = 0x7fff;
  const auto past = scw::warning::evaluate_object(near, cfg);
  CHECK(past.too_close);
  CHECK(past.distance_mm <= e.distance_mm);
}

TEST_CASE("warning model: configurations the build cannot take are refused by name", "[hls]") {
  auto cfg = scw::host::warning::to_fixed(scw::fixtures::thesis_setup());
  auto bad = cfg;
  bad.d_limit_q4 = 16 * 129;
  CHECK_THROWS_WITH(scw::hls::warning::Warning<Params>(bad), Catch::Contains("disparity limit"));
  bad = cfg;
  bad.baseline_q8 = 0;
  CHECK_THROWS_WITH(scw::hls::warning::Warning<Params>(bad), Catch::Contains("baseline"));
  bad = cfg;
  bad.high_mm = 30000;
  CHECK_THROWS_WITH(scw::hls::warning::Warning<Params>(bad), Catch::Contains("high threshold"));
}
