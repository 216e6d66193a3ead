// SPDX-License-Identifier: Apache-2.0
// [soak] The small build's Verilated scw_pipeline against the C++ chain over 100 frames of varied
// content with a broken frame every 10 and random stalls; resets at random cycles in mid-frame;
// and the checkers themselves (a divergence is found where it is, faults give the results they
// should).
#include <catch2/catch.hpp>
#include <string>

#include "host/io/tsukuba.hpp"
#include "host/soak/reset_trials.hpp"
#include "host/soak/soak.hpp"
#include "sim/rtl/verilated_harness.hpp"
#include "tests/common/scoped_env.hpp"

namespace {

using namespace scw::host::soak;

RealPair tsukuba() {
  const auto p = scw::host::io::read_tsukuba_pair(SCW_DATA_DIR "/tsukuba");
  return {p.left, p.right};
}

}  // namespace

TEST_CASE("100 frames, a broken one every 10, random stalls: top = C++ chain = reference",
          "[soak][rtl]") {
  SoakOptions o;
  o.frames = 100;
  o.malformed_every = 10;
  o.seed = 7;
  o.real = tsukuba();
  const auto s = run_soak(o);
  INFO(s.to_json().dump(1));
  CHECK(s.passed());
  CHECK(s.deadlocks == 0);
  CHECK(s.divergences == 0);
  CHECK(s.flag_mismatches == 0);
  CHECK(s.reference_mismatches == 0);
  CHECK(s.malformed == 9);  // frames 9, 19, .. 89 (never the last)
  for (const char* f : {"short row", "cut frame", "sof mid-frame", "stray beats"})
    CHECK(s.faults.at(f) >= 2);
  for (const char* c : {"street", "clutter", "real", "noise"}) CHECK(s.content.at(c) >= 10);
  // A sof in mid-frame makes two results of one frame.
  CHECK(s.results == 100 + s.faults.at("sof mid-frame"));
  CHECK(s.reference_checked == 100 - 9);
}

TEST_CASE("resets at random cycles in mid-frame: the top then behaves as a fresh C++ chain",
          "[soak][rtl]") {
  ResetOptions o;
  o.trials = 60;
  o.seed = 3;
  o.real = tsukuba();
  const auto s = run_reset_trials(o);
  INFO(s.to_json().dump(1));
  CHECK(s.trials == 60);
  CHECK(s.failures == 0);
  // The resets cut every stage at work, and the labelling stage in each of its phases, Emit
  // beside them among them.
  for (const char* st : {"rectify_left", "rectify_right", "disparity", "road", "labelling",
                         "warning"})
    CHECK(s.busy.count(st) == 1);
  for (const char* ph : {"init", "frame", "drain", "resolve", "frame+emit"})
    CHECK(s.labelling.count(ph) == 1);
}

TEST_CASE("compare_runs names the first differing result, its cycle, and results missing",
          "[soak]") {
  RunOutput a;
  for (int i = 0; i < 4; ++i) {
    scw::hls::pipeline::PipelineResultPacket r{};
    r.data.frame.objects = static_cast<decltype(r.data.frame.objects)>(i);
    r.last = true;
    a.results.push_back(r);
    a.result_cycles.push_back(1000 * (i + 1));
  }
  CHECK(compare_runs(a, a).first == 0);
  CHECK_FALSE(compare_runs(a, a).second);
  auto b = a;
  b.result_cycles[2] += 1;
  b.results[3].data.input_error_left = true;
  const auto [n, d] = compare_runs(a, b);
  CHECK(n == 2);
  REQUIRE(d);
  CHECK(d->frame == 2);
  CHECK(d->cycle == 3000);
  CHECK_THAT(d->what, Catch::Contains("result cycle"));
  b = a;
  b.results.pop_back();
  b.result_cycles.pop_back();
  const auto m = compare_runs(a, b);
  CHECK(m.first == 1);
  CHECK(m.second->frame == 3);
  CHECK_THAT(m.second->what, Catch::Contains("the RTL gave no result"));
}

TEST_CASE("each fault breaks its camera's frame and says which results must be flagged",
          "[soak]") {
  ContentFrame f{cv::Mat(8, 16, CV_8U, cv::Scalar(7)), cv::Mat(8, 16, CV_8U, cv::Scalar(9)),
                 Content::street};
  const std::size_t whole = 8 * 16;
  SoakStream s;
  append_frame(s, f, 0, Fault::none, true, 1);
  CHECK(s.left.size() == whole);
  CHECK(s.expected.size() == 1);
  append_frame(s, f, 1, Fault::short_row, false, 1);
  CHECK(s.left.size() == 2 * whole);
  CHECK(s.right.size() < 2 * whole);
  CHECK(s.expected.back().right_broken);
  CHECK_FALSE(s.expected.back().left_broken);
  append_frame(s, f, 2, Fault::sof_mid_frame, true, 1);
  CHECK(s.expected.size() == 4);  // two results of one frame, both broken on both cameras
  CHECK(s.expected[2].left_broken);
  CHECK(s.expected[3].right_broken);
  append_frame(s, f, 3, Fault::stray_beats, true, 1);
  CHECK(s.left.size() > 4 * whole);
  CHECK_FALSE(s.left[3 * whole].sof);  // stray beats come before the frame's sof
  const auto before = s.left.size();
  append_frame(s, f, 4, Fault::cut_frame, true, 1);
  CHECK(s.left.size() - before < whole);
  CHECK((s.left.size() - before) % 16 == 0);  // whole rows, then the link drops
}

TEST_CASE("a trace window that is not FROM:TO is refused with the fix", "[soak][sim]") {
  scw::test::ScopedEnv window("SCW_FST_WINDOW", "20:10");
  CHECK_THROWS_WITH(scw::sim::TraceWindow::from_env(), Catch::Contains("give FROM:TO"));
  window.set("10:20");
  const auto w = scw::sim::TraceWindow::from_env();
  CHECK(w.holds(10));
  CHECK(w.holds(20));
  CHECK_FALSE(w.holds(21));
}
