// SPDX-License-Identifier: Apache-2.0
// [hls] The pipeline's HLS top (hls/pipeline/pipeline_top.hpp: the stage tops as DATAFLOW
// processes over scw::hls::stream links, a frame a call) gives the clocked C++ chain's
// (sim::PipelineChain) frame results and object table, on synthetic pairs at the small build.
#include <catch2/catch.hpp>
#include <cstdint>
#include <memory>
#include <type_traits>
#include <vector>

#include "hls/common/stream.hpp"
#include "hls/pipeline/pipeline_params.hpp"
#include "hls/pipeline/pipeline_top.hpp"
#include "hls/tops/tops.hpp"
#include "host/pipeline/setup.hpp"
#include "host/pipeline/synthetic.hpp"
#include "sim/pipeline/pipeline_chain.hpp"

namespace {

namespace hp = scw::hls::pipeline;
namespace hostp = scw::host::pipeline;
using scw::sim::Engine;
using scw::sim::PipelineEngines;

/// `frames` pairs through both, compared frame by frame. `road`: a street whose road the stage
/// fits and removes (frame-level state that the top carries from call to call); otherwise a
/// textured background and a box, the right camera shifted half a pixel so the rectifiers work.
/// `through_c_synthesis_top`: the frames go through hls/tops' scw_pipeline_top (built at
/// SCW_HLS_BUILD, this target's SmallPipeline<1>, its stages `static` in it) instead of
/// pipeline_frame on stages of the test's own.
template <int P>
void check_top_equals_chain(int frames, bool road, bool through_c_synthesis_top = false) {
  using Build = hp::SmallPipeline<P>;
  const int w = 64, h = 32;
  hostp::StageOptions opt;
  opt.mode = scw::disparity::Mode::opencv;
  opt.min_area = 20;
  opt.warning.focal_px = 100.0;
  opt.warning.baseline_m = 0.2;
  if (road) {
    opt.camera_height_m = 0.45;  // the nominal road is not the scene's: the fit must move it
    opt.warning.cv_px = 8.0;
    opt.road_min_count = 50;
  }
  std::vector<cv::Mat> ls, rs;
  for (int k = 0; k < frames; ++k) {
    std::vector<hostp::SyntheticBox> boxes;
    if (road)  // a road rising 1 px every 2 rows from row 12
      for (int y = 12; y < h; ++y) boxes.push_back({0, y, w, y + 1, 2 + (y - 12) / 2});
    boxes.push_back({w / 3, 6, w / 3 + w / 5, h - 4, 11});
    const auto pair = hostp::synthetic_pair(w, h, 2, boxes, 31u + static_cast<std::uint32_t>(k));
    ls.push_back(pair.left);
    rs.push_back(pair.right);
  }
  auto knots = hostp::identity_knots(w, h, Build::kGridLog2);
  auto right_knots = knots;
  if (!road)
    for (auto& k : right_knots) k.y -= 64;  // half a pixel up: Q.7
  const auto setup = hostp::make_setup(w, h, Build::kGridLog2, opt, knots, right_knots, 2);
  const auto left = hostp::frames_beats<P>(ls);
  const auto right = hostp::frames_beats<P>(rs);

  scw::sim::PipelineChain<Build> chain(setup, PipelineEngines::all(Engine::cpp), left, right);
  chain.run(static_cast<std::size_t>(frames), 400000);
  REQUIRE(chain.results().size() == static_cast<std::size_t>(frames));

  auto stages = std::make_unique<hp::PipelineStages<Build>>(setup);  // its stage settings
  hp::pipeline_load_knots(*stages, setup.left_knots.data(), setup.right_knots.data(),
                          setup.knot_cols, setup.knot_rows);
  constexpr int kFrame = Build::kMaxWidthPx / P * Build::kMaxHeight;
  const int n = w / P * h;
  std::vector<hp::PipelineResultPacket> results;
  std::vector<scw::hls::labelling::LabelPacket> table;
  for (int k = 0; k < frames; ++k) {
    scw::hls::stream<typename Build::rectify::pixel_beat, kFrame> l("left"), r("right");
    scw::hls::stream<hp::PipelineResultPacket, 2> res("result");
    scw::hls::stream<scw::hls::labelling::LabelPacket, Build::kMaxObjects + 1> words("table");
    for (int i = k * n; i < (k + 1) * n; ++i) {
      l.write(left[static_cast<std::size_t>(i)]);
      r.write(right[static_cast<std::size_t>(i)]);
    }
    if (through_c_synthesis_top) {
      if constexpr (std::is_same_v<Build, scw::hls::tops::Build>) {
        const int cols = k == 0 ? setup.knot_cols : 0;  // the knots go in with the first call
        scw_pipeline_top(l, r, res, words, setup.left_knots.data(), setup.right_knots.data(), cols,
                         setup.knot_rows, setup);
      } else {
        FAIL("scw_pipeline_top is built at SCW_HLS_BUILD, not at this P");
      }
    } else {
      hp::pipeline_frame(*stages, l, r, res, words);
    }
    CHECK(l.empty());
    CHECK(r.empty());
    while (!res.empty()) results.push_back(res.read());
    while (!words.empty()) table.push_back(words.read());
  }
  CHECK(results == chain.results());
  CHECK(table == chain.object_table());
  for (const auto& res : results) CHECK(res.data.frame.objects >= 1);  // the box, every frame
  if (road && !through_c_synthesis_top)                                // the fit moved the road
    CHECK(stages->road.line() != setup.road.nominal);
}

}  // namespace

TEST_CASE("the pipeline top, a frame a call, equals the C++ chain's results, P = 1",
          "[pipeline][hls]") {
  check_top_equals_chain<1>(2, false);
}

TEST_CASE("the pipeline top equals the C++ chain's results, P = 2", "[pipeline][hls]") {
  check_top_equals_chain<2>(2, false);
}

TEST_CASE("the pipeline top with a road to fit equals the C++ chain's results, P = 1",
          "[pipeline][hls]") {
  check_top_equals_chain<1>(3, true);
}

// One process, one call of this test: the top's stages are `static`, configured by its first
// call (as in hardware, where they are registers), so a second test through it would find them
// mid-stream.
TEST_CASE(
    "the C-synthesis top scw_pipeline_top, with a road to fit, equals the C++ chain's "
    "results, P = 1",
    "[pipeline][hls]") {
  check_top_equals_chain<1>(3, true, true);
}
