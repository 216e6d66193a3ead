// SPDX-License-Identifier: Apache-2.0
// [pipeline] The whole pipeline at the small build: the C++ chain, the chain of Verilated blocks
// and the Verilated scw_pipeline top agree clock for clock; results survive random gaps and
// backpressure; broken frames are flagged and the next frame is right; on a Tsukuba crop the
// frame results equal the floating-point chain's (cv::StereoBM, flood fill, Eigen).
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "hls/pipeline/pipeline_params.hpp"
#include "host/disparity/run_model.hpp"
#include "host/io/tsukuba.hpp"
#include "host/pipeline/reference_chain.hpp"
#include "host/pipeline/setup.hpp"
#include "host/pipeline/synthetic.hpp"
#include "host/road/run_model.hpp"
#include "sim/builds/pipeline_small_rtl.hpp"
#include "sim/pipeline/pipeline_chain.hpp"
#include "sim/pipeline/pipeline_top.hpp"

namespace {

using scw::sim::Engine;
using scw::sim::PipelineEngines;
using Result = scw::hls::pipeline::PipelineResultPacket;

template <int P>
using Build = scw::sim::small_build::Build<P>;
template <int P>
using Rtl = scw::sim::small_build::Rtl<P>;

template <int P>
using Chain = scw::sim::small_build::Chain<P>;

/// A synthetic pair (host/pipeline/synthetic.hpp): a textured background at disparity 3 and a
/// box at 11. small_setup's right-camera map moves the right image half a pixel, so the
/// rectifiers have work to do.
scw::host::pipeline::SyntheticPair make_scene(int w, int h, std::uint32_t seed) {
  return scw::host::pipeline::synthetic_pair(w, h, 3, {{w / 3, h / 4, w / 3 + w / 4, h * 3 / 4, 11}},
                                             seed);
}

/// The settings of the small build's runs: opencv mode, disparities 0 .. 15, 2 x 2 tiles,
/// objects of 20 px, a camera of f 100 px and b 0.2 m.
scw::host::pipeline::StageOptions small_options() {
  return scw::host::pipeline::small_build_options();
}

/// A street for the road stage: a wall at disparity 2, a road rising 1 px every 2 rows from
/// row 12 (0.5 px a row from a horizon at row 8), a box at 12 standing on it.
scw::host::pipeline::SyntheticPair make_road_scene(int w, int h, std::uint32_t seed) {
  std::vector<scw::host::pipeline::SyntheticBox> boxes;
  for (int y = 12; y < h; ++y) boxes.push_back({0, y, w, y + 1, 2 + (y - 12) / 2});
  boxes.push_back({w / 3, 6, w / 3 + w / 5, h - 4, 12});
  return scw::host::pipeline::synthetic_pair(w, h, 2, boxes, seed);
}

/// small_options for make_road_scene: the camera 0.45 m above the road, so the nominal road
/// (0.44 px a row) is not the scene's and the stage's fit has to move it; the horizon row 8.
scw::host::pipeline::StageOptions road_options(int w) {
  auto o = small_options();
  o.camera_height_m = 0.45;
  o.warning.cu_px = 0.5 * (w - 1);
  o.warning.cv_px = 8.0;
  o.road_min_count = 50;  // a 64 x 32 frame has 2,048 pixels
  return o;
}

scw::sim::PipelineSetup small_setup(int w, int h, bool shifted_right) {
  auto left = scw::host::pipeline::identity_knots(w, h, Build<1>::kGridLog2);
  auto right = left;
  if (shifted_right)
    for (auto& k : right) k.y -= 64;  // half a pixel up: Q.7
  return scw::host::pipeline::make_setup(w, h, Build<1>::kGridLog2, small_options(),
                                         std::move(left), std::move(right), 2);
}

/// `road`: make_road_scene with road_options, and the road stage must have removed pixels and
/// moved its road; otherwise make_scene with small_options.
template <int P>
void check_three_ways(int frames, bool road = false) {
  const int w = 64, h = 32;
  std::vector<cv::Mat> ls, rs;
  for (int k = 0; k < frames; ++k) {
    const auto seed = 11u + static_cast<std::uint32_t>(k);
    const auto s = road ? make_road_scene(w, h, seed) : make_scene(w, h, seed);
    ls.push_back(s.left);
    rs.push_back(s.right);
  }
  const auto left = scw::host::pipeline::frames_beats<P>(ls);
  const auto right = scw::host::pipeline::frames_beats<P>(rs);
  auto setup = small_setup(w, h, true);
  if (road) {
    auto knots = scw::host::pipeline::identity_knots(w, h, Build<1>::kGridLog2);
    setup = scw::host::pipeline::make_setup(w, h, Build<1>::kGridLog2, road_options(w), knots,
                                            knots, 2);
  }

  Chain<P> cpp(setup, PipelineEngines::all(Engine::cpp), left, right);
  cpp.disparity().record(true);
  cpp.road().record(true);
  cpp.run(static_cast<std::size_t>(frames), 200000);
  if (road) {
    // The road stage took road pixels out of every frame, and its fit moved the road.
    std::size_t removed = 0;
    const auto& in = cpp.disparity().recorded();
    const auto& out = cpp.road().recorded();
    REQUIRE(in.size() == out.size());
    for (std::size_t i = 0; i < in.size(); ++i)
      for (int k = 0; k < P; ++k) removed += in[i].px[k] != out[i].px[k];
    CHECK(removed > static_cast<std::size_t>(frames * w * 3));
    scw::road::RoadFilter f(setup.road);
    cv::Mat map(h, w, CV_16UC1);
    for (int k = 0; k < 2; ++k) {
      for (int i = 0; i < w * h / P; ++i)
        for (int j = 0; j < P; ++j)
          map.at<std::uint16_t>(i * P / w, (i * P) % w + j) =
              in[static_cast<std::size_t>(k * w * h / P + i)].px[j];
      f.filter(map);
    }
    CHECK(f.road() != setup.road.nominal);
  }
  Chain<P> rtl(setup, scw::sim::small_build::rtl_engines<P>(), left, right);
  rtl.run(static_cast<std::size_t>(frames), 200000);
  scw::sim::small_build::Top<P> top(setup);
  const auto t = top.run(left, right, static_cast<std::size_t>(frames), 200000);

  REQUIRE(cpp.results().size() == static_cast<std::size_t>(frames));
  CHECK(rtl.results() == cpp.results());
  CHECK(t.results == cpp.results());
  CHECK(rtl.result_cycles() == cpp.result_cycles());
  CHECK(t.result_cycles == cpp.result_cycles());
  CHECK(top.errors() == 0u);
  // The object table leaves the top word for word as the C++ chain's labelling stage sent it:
  // per frame its object words, then the status word (last) that counts them.
  CHECK(rtl.object_table() == cpp.object_table());
  CHECK(t.object_table == cpp.object_table());
  std::size_t words = 0, frames_seen = 0;
  for (const auto& word : cpp.object_table()) {
    if (!word.last) {
      CHECK_FALSE(word.data.is_status);
      ++words;
      continue;
    }
    REQUIRE(word.data.is_status);
    CHECK(word.data.status.objects == words);
    CHECK(word.data.status.objects == cpp.results()[frames_seen].data.frame.objects);
    words = 0;
    ++frames_seen;
  }
  CHECK(frames_seen == static_cast<std::size_t>(frames));
  // Every link moved the same beats at the same cycles, C++ and RTL.
  const auto a = cpp.report(), b = rtl.report();
  REQUIRE(a.fifos.size() == b.fifos.size());
  for (std::size_t i = 0; i < a.fifos.size(); ++i) {
    INFO(a.fifos[i].name);
    CHECK(a.fifos[i].beats == b.fifos[i].beats);
    CHECK(a.fifos[i].max_occupancy == b.fifos[i].max_occupancy);
  }
  REQUIRE(a.stages.size() == b.stages.size());
  for (std::size_t i = 0; i < a.stages.size(); ++i) {
    INFO(a.stages[i].name);
    REQUIRE(a.stages[i].frames.size() == b.stages[i].frames.size());
    for (std::size_t k = 0; k < a.stages[i].frames.size(); ++k) {
      CHECK(a.stages[i].frames[k].first_in == b.stages[i].frames[k].first_in);
      CHECK(a.stages[i].frames[k].last_out == b.stages[i].frames[k].last_out);
    }
  }
  // The box is found, in every frame, and no flag is raised.
  for (const Result& r : cpp.results()) {
    CHECK(r.data.frame.objects >= 1);
    CHECK_FALSE(r.data.input_error_left);
    CHECK_FALSE(r.data.input_error_right);
    CHECK_FALSE(r.data.frame.stream_error);
  }
}

}  // namespace

TEST_CASE("C++ chain, RTL chain and the scw_pipeline top agree clock for clock, P = 1",
          "[pipeline][rtl]") {
  check_three_ways<1>(3);
}

TEST_CASE("C++ chain, RTL chain and the scw_pipeline top agree clock for clock, P = 2",
          "[pipeline][rtl]") {
  check_three_ways<2>(3);
}

TEST_CASE("with a road: the road stage removes it and follows it, C++ chain = RTL chain = top",
          "[pipeline][rtl][road]") {
  SECTION("P = 1") { check_three_ways<1>(3, true); }
  SECTION("P = 2") { check_three_ways<2>(3, true); }
}

namespace {

/// `frames` synthetic frames of w x h (each its own texture) as both cameras' beats.
template <int P>
std::pair<std::vector<scw::hls::Beat<std::uint8_t, P>>, std::vector<scw::hls::Beat<std::uint8_t, P>>>
scene_beats(int w, int h, int frames) {
  std::vector<cv::Mat> ls, rs;
  for (int k = 0; k < frames; ++k) {
    const auto s = make_scene(w, h, 100u + static_cast<std::uint32_t>(k));
    ls.push_back(s.left);
    rs.push_back(s.right);
  }
  return {scw::host::pipeline::frames_beats<P>(ls), scw::host::pipeline::frames_beats<P>(rs)};
}

}  // namespace

namespace {

/// 20 frames under random input gaps and output backpressure, at P pixels per beat.
template <int P>
void check_stalls() {
  const int w = 48, h = 24, frames = 20;
  const auto [left, right] = scene_beats<P>(w, h, frames);
  const auto setup = small_setup(w, h, false);
  Chain<P> calm(setup, PipelineEngines::all(Engine::cpp), left, right);
  calm.run(frames, 400000);
  REQUIRE(calm.results().size() == static_cast<std::size_t>(frames));
  for (std::uint64_t seed : {1u, 2u}) {
    const auto stalls = scw::sim::StallPattern::parse("random:" + std::to_string(seed));
    Chain<P> cpp(setup, PipelineEngines::all(Engine::cpp), left, right, stalls, stalls);
    cpp.run(frames, 2000000);
    Chain<P> rtl(setup, scw::sim::small_build::rtl_engines<P>(), left, right, stalls, stalls);
    rtl.run(frames, 2000000);
    scw::sim::small_build::Top<P> top(setup);
    const auto t = top.run(left, right, frames, 2000000, stalls, stalls);
    INFO("seed " << seed);
    CHECK(cpp.results() == calm.results());
    CHECK(rtl.results() == calm.results());
    CHECK(t.results == calm.results());
    CHECK(rtl.result_cycles() == cpp.result_cycles());
    CHECK(t.result_cycles == cpp.result_cycles());
    CHECK(rtl.object_table() == cpp.object_table());
    CHECK(t.object_table == cpp.object_table());
    CHECK(cpp.cycles() > calm.cycles());  // the gaps did cost time
  }
}

}  // namespace

TEST_CASE("20 frames under random input gaps and output backpressure: same results, no deadlock",
          "[pipeline][rtl][sim]") {
  SECTION("P = 1") { check_stalls<1>(); }
  SECTION("P = 2: the labelling stage's two lanes") { check_stalls<2>(); }
}

TEST_CASE(
    "two threads: the chain of Verilated blocks and of C++ models report what one thread does",
    "[pipeline][rtl][sim]") {
  const int w = 48, h = 24, frames = 4;
  const auto [left, right] = scene_beats<1>(w, h, frames);
  const auto setup = small_setup(w, h, true);
  const auto stalls = scw::sim::StallPattern::parse("random:9");
  for (const auto& engines :
       {scw::sim::small_build::rtl_engines<1>(), PipelineEngines::all(Engine::cpp)}) {
    Chain<1> one(setup, engines, left, right, stalls, stalls, 1);
    one.run(frames, 2000000);
    Chain<1> two(setup, engines, left, right, stalls, stalls, 2);
    REQUIRE(two.simulator().threads() == 2);
    two.run(frames, 2000000);
    REQUIRE(one.results().size() == static_cast<std::size_t>(frames));
    CHECK(two.results() == one.results());
    CHECK(two.result_cycles() == one.result_cycles());
    CHECK(two.object_table() == one.object_table());
    // Every FIFO's beats and fullest moment, every block's first and last beat of every frame.
    CHECK(two.report().text() == one.report().text());
    CHECK(two.timing().period == one.timing().period);
  }
}

// Also under random RAM contents (x-seed1): the rows a frame cut short right after reset never
// sent read 0 in the rectifier (its blank row slots), not whatever the RAM held, so the RTL and
// the C++ model agree on the flagged frame too.
TEST_CASE("broken input frames are flagged in their result, the next frame is right",
          "[pipeline][rtl]") {
  constexpr int P = 1;
  using B = scw::hls::Beat<std::uint8_t, P>;
  const int w = 48, h = 24;
  const auto [good_l, good_r] = scene_beats<P>(w, h, 1);
  const auto setup = small_setup(w, h, false);
  Chain<P> ref(setup, PipelineEngines::all(Engine::cpp), good_l, good_r);
  ref.run(1, 100000);
  const Result good = ref.results()[0];

  // Each case: the left stream's broken frame, then a good frame; the right stream two good
  // frames. Expected flags: the broken frame's left flag only.
  struct Case {
    const char* name;
    std::vector<B> broken;
  };
  std::vector<Case> cases;
  {
    auto b = good_l;  // a short row: row 3 ends two pixels early
    b.erase(b.begin() + 3 * w + w - 2, b.begin() + 3 * w + w);
    b[static_cast<std::size_t>(3 * w + w - 3)].eol = true;
    cases.push_back({"short row", b});
  }
  {
    auto b = good_l;  // the frame cut short: only 10 rows, then the next frame's sof
    b.resize(static_cast<std::size_t>(10 * w));
    cases.push_back({"frame cut short", b});
  }
  {
    auto b = good_l;  // a sof in mid-frame: row 5 starts with sof (the frame restarts there)
    b[static_cast<std::size_t>(5 * w)].sof = true;
    cases.push_back({"sof mid-frame", b});
  }
  for (const Case& c : cases) {
    DYNAMIC_SECTION(c.name) {
      std::vector<B> left = c.broken;
      left.insert(left.end(), good_l.begin(), good_l.end());
      std::vector<B> right = good_r;
      right.insert(right.end(), good_r.begin(), good_r.end());
      // A sof in mid-frame makes two frames of the left stream out of one: the right stream
      // needs the same count, so it gets its own restart at the same place.
      if (std::string(c.name) == "sof mid-frame") right[static_cast<std::size_t>(5 * w)].sof = true;
      Chain<P> cpp(setup, PipelineEngines::all(Engine::cpp), left, right);
      const std::size_t n = std::string(c.name) == "sof mid-frame" ? 3 : 2;
      cpp.run(n, 400000);
      scw::sim::small_build::Top<P> top(setup);
      const auto t = top.run(left, right, n, 400000);
      CHECK(t.results == cpp.results());
      CHECK(t.result_cycles == cpp.result_cycles());
      const auto& r = cpp.results();
      CHECK(r[0].data.input_error_left);
      CHECK(r.back() == good);  // the frame after the broken one is exact
      CHECK_FALSE(r.back().data.input_error_left);
      CHECK_FALSE(r.back().data.input_error_right);
    }
  }
}

TEST_CASE("a Tsukuba crop: RTL chain = C++ chain = the floating-point chain's frame result",
          "[pipeline][rtl][ref]") {
  constexpr int P = 1;
  const auto [l, r] = scw::host::io::read_tsukuba_pair(SCW_DATA_DIR "/tsukuba");
  // The lamp, the head and the table: 128 x 96 from (128, 96).
  const cv::Rect crop(128, 96, 128, 96);
  const cv::Mat lc = l(crop).clone(), rc = r(crop).clone();
  auto opt = small_options();
  opt.warning.focal_px = 615.0;  // the camera scripts/run.sh assumes for Tsukuba
  opt.warning.baseline_m = 0.1;
  opt.min_area = 60;
  const auto knots = scw::host::pipeline::identity_knots(128, 96, Build<P>::kGridLog2);
  const auto setup = scw::host::pipeline::make_setup(128, 96, Build<P>::kGridLog2, opt, knots,
                                                     knots, 1);
  const auto left = scw::host::pipeline::frames_beats<P>({lc, lc});
  const auto right = scw::host::pipeline::frames_beats<P>({rc, rc});
  Chain<P> cpp(setup, PipelineEngines::all(Engine::cpp), left, right);
  cpp.run(2, 200000);
  Chain<P> rtl(setup, scw::sim::small_build::rtl_engines<P>(), left, right);
  rtl.run(2, 200000);
  REQUIRE(cpp.results().size() == 2);
  CHECK(rtl.results() == cpp.results());
  CHECK(cpp.results()[1] == cpp.results()[0]);  // the same pair twice: the same answer

  const auto ref = scw::host::pipeline::reference_frame(lc, rc, 9, opt);
  REQUIRE(ref.result.objects >= 2);
  REQUIRE(ref.result.index >= 0);
  CHECK(scw::host::pipeline::reference_mismatch(cpp.results()[0].data.frame, ref, lc.cols,
                                                lc.rows, opt) == "");
}

TEST_CASE("a setup no stage can take is refused with the reason", "[pipeline]") {
  auto s = small_setup(64, 32, false);
  s.width = 130;
  CHECK_THROWS_WITH(Chain<1>(s, PipelineEngines::all(Engine::cpp), {}, {}),
                    Catch::Contains("width 130"));
  s = small_setup(64, 32, false);
  s.left_knots.pop_back();
  CHECK_THROWS_WITH(Chain<1>(s, PipelineEngines::all(Engine::cpp), {}, {}),
                    Catch::Contains("knots"));
  s = small_setup(64, 32, false);
  s.lead_rows = 15;
  CHECK_THROWS_WITH(Chain<1>(s, PipelineEngines::all(Engine::cpp), {}, {}),
                    Catch::Contains("lead"));
  // P = 2's chain has no Verilated rectifier: asking for one names the block.
  CHECK_THROWS_WITH(Chain<2>(small_setup(64, 32, false), PipelineEngines::all(Engine::rtl), {}, {}),
                    Catch::Contains("frame check RTL is not built"));
}

