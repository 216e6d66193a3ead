// SPDX-License-Identifier: Apache-2.0
// [hls] C simulation of every stage's C-synthesis top (hls/tops, built here at SmallPipeline<1>),
// as a vendor test bench would run it: the frames a stage sees in the clocked C++ chain
// (sim::PipelineChain, every block its clocked model, the RTL's twins) go through the top a
// frame a call, and what comes out must be what the chain's next link carried. The pipeline's
// own top is compared in test_pipeline_hls.cpp. Each top keeps its kernel `static`, so each is
// called from one test case only (CTest runs each case in its own process).
#include <catch2/catch.hpp>
#include <cstdint>
#include <memory>
#include <vector>

#include "hls/road/road.hpp"
#include "hls/tops/tops.hpp"
#include "host/pipeline/setup.hpp"
#include "host/pipeline/synthetic.hpp"
#include "sim/pipeline/pipeline_chain.hpp"

namespace {

namespace tops = scw::hls::tops;
using Build = tops::Build;
static_assert(Build::kPpc == 1, "this test bench is written for the build it sets, P = 1");

constexpr int kW = 64, kH = 32, kFrames = 3;
constexpr int kN = kW / Build::kPpc * kH;  // beats of one camera's frame

/// The chain's run of three street frames (a road the road stage fits and removes, a box on it,
/// the right camera half a pixel up so the rectifiers interpolate), the optional ground filter
/// on between road and labelling, and every link a top is compared on recorded.
struct ChainRun {
  scw::sim::PipelineSetup setup;
  std::vector<Build::rectify::pixel_beat> left, right;
  std::vector<Build::rectify::pixel_beat> rect_left, rect_right;
  std::vector<Build::disparity::disp_beat> disparity;
  std::vector<Build::road::out_beat> road;        // what the road stage leaves
  std::vector<Build::labelling::in_beat> ground;  // what the ground filter leaves
  std::vector<scw::hls::labelling::LabelPacket> objects;
  std::vector<scw::hls::warning::FrameResult> results;
};

const ChainRun& chain_run() {
  static const ChainRun run = [] {
    namespace hostp = scw::host::pipeline;
    hostp::StageOptions opt;
    opt.mode = scw::disparity::Mode::opencv;
    opt.min_area = 20;
    opt.warning.focal_px = 100.0;
    opt.warning.baseline_m = 0.2;
    opt.warning.cv_px = 8.0;
    opt.camera_height_m = 0.45;  // not the scene's road: the fit must move it
    opt.road_min_count = 50;
    std::vector<cv::Mat> ls, rs;
    for (int k = 0; k < kFrames; ++k) {
      std::vector<hostp::SyntheticBox> boxes;
      for (int y = 12; y < kH; ++y) boxes.push_back({0, y, kW, y + 1, 2 + (y - 12) / 2});
      boxes.push_back({kW / 3, 6, kW / 3 + kW / 5, kH - 4, 11});
      const auto pair =
          hostp::synthetic_pair(kW, kH, 2, boxes, 57u + static_cast<std::uint32_t>(k));
      ls.push_back(pair.left);
      rs.push_back(pair.right);
    }
    const auto knots = hostp::identity_knots(kW, kH, Build::kGridLog2);
    auto right_knots = knots;
    for (auto& k : right_knots) k.y -= 64;  // half a pixel up: Q.7
    ChainRun r;
    r.setup = hostp::make_setup(kW, kH, Build::kGridLog2, opt, knots, right_knots, 2);
    r.setup.ground = scw::hls::ground::GroundConfig{};
    r.left = hostp::frames_beats<Build::kPpc>(ls);
    r.right = hostp::frames_beats<Build::kPpc>(rs);
    scw::sim::PipelineChain<Build> chain(
        r.setup, scw::sim::PipelineEngines::all(scw::sim::Engine::cpp), r.left, r.right);
    chain.rect_left().record(true);
    chain.rect_right().record(true);
    chain.disparity().record(true);
    chain.road().record(true);
    chain.labelling_input().record(true);
    chain.run(kFrames, 1'000'000);
    REQUIRE(chain.results().size() == static_cast<std::size_t>(kFrames));
    r.rect_left = chain.rect_left().recorded();
    r.rect_right = chain.rect_right().recorded();
    r.disparity = chain.disparity().recorded();
    r.road = chain.road().recorded();
    r.ground = chain.labelling_input().recorded();
    r.objects = chain.object_table();
    for (const auto& res : chain.results()) r.results.push_back(res.data.frame);
    return r;
  }();
  return run;
}

template <typename Stream, typename T>
void write_frame(Stream& s, const std::vector<T>& beats, int frame) {
  REQUIRE(beats.size() >= static_cast<std::size_t>((frame + 1) * kN));
  for (int i = frame * kN; i < (frame + 1) * kN; ++i) s.write(beats[static_cast<std::size_t>(i)]);
}

template <typename Stream, typename T>
void drain(Stream& s, std::vector<T>& into) {
  while (!s.empty()) into.push_back(s.read());
}

/// The words of frame `frame` of an object table: its objects and the status word (`last`).
std::vector<scw::hls::labelling::LabelPacket> frame_words(
    const std::vector<scw::hls::labelling::LabelPacket>& table, int frame) {
  std::vector<scw::hls::labelling::LabelPacket> out;
  int k = 0;
  for (const auto& w : table) {
    if (k == frame) out.push_back(w);
    if (w.last && ++k > frame) break;
  }
  return out;
}

template <typename T>
std::vector<T> frames_of(const std::vector<T>& v) {  // the first kFrames frames of a link
  REQUIRE(v.size() >= static_cast<std::size_t>(kFrames * kN));
  return std::vector<T>(v.begin(), v.begin() + kFrames * kN);
}

}  // namespace

TEST_CASE("C-synthesis top scw_frame_check_top passes good frames on and flags none",
          "[pipeline][hls]") {
  const auto& c = chain_run();
  std::vector<Build::rectify::pixel_beat> out;
  std::vector<scw::hls::pipeline::FrameFlagPacket> flags;
  for (int k = 0; k < kFrames; ++k) {
    tops::Pixels in("in"), o("out");
    tops::Flags f("flags");
    write_frame(in, c.left, k);
    scw_frame_check_top(in, o, f, {kW, kH}, kN);
    CHECK(in.empty());
    drain(o, out);
    drain(f, flags);
  }
  CHECK(out == frames_of(c.left));
  REQUIRE(flags.size() == static_cast<std::size_t>(kFrames));
  for (const auto& f : flags) CHECK_FALSE(f.data.error);
}

TEST_CASE(
    "C-synthesis tops scw_map_grid_top and scw_rectify_top give the chain's rectified "
    "right camera",
    "[pipeline][hls]") {
  const auto& c = chain_run();
  std::vector<Build::rectify::pixel_beat> out;
  for (int k = 0; k < kFrames; ++k) {
    tops::Pixels raw("raw"), rect("rect");
    tops::Maps map("map");
    const int cols = k == 0 ? c.setup.knot_cols : 0;  // the knots go in with the first call
    scw_map_grid_top(c.setup.right_knots.data(), cols, c.setup.knot_rows, map, {kW, kH}, kN);
    write_frame(raw, c.right, k);
    scw_rectify_top(raw, map, rect, {kW, kH, c.setup.lead_rows}, kN);
    CHECK(raw.empty());
    CHECK(map.empty());
    drain(rect, out);
  }
  CHECK(out == frames_of(c.rect_right));
}

TEST_CASE("C-synthesis top scw_disparity_top gives the chain's disparity", "[pipeline][hls]") {
  const auto& c = chain_run();
  std::vector<Build::disparity::disp_beat> out;
  for (int k = 0; k < kFrames; ++k) {
    tops::Pixels l("left"), r("right");
    tops::Disparities d("disparity");
    write_frame(l, c.rect_left, k);
    write_frame(r, c.rect_right, k);
    scw_disparity_top(l, r, d, c.setup.disparity_config(), kN);
    drain(d, out);
  }
  CHECK(out == frames_of(c.disparity));
}

TEST_CASE("C-synthesis top scw_road_top gives what the chain's road stage left",
          "[pipeline][hls]") {
  const auto& c = chain_run();
  std::vector<Build::road::out_beat> out;
  std::vector<scw::hls::road::Line> lines;
  for (int k = 0; k < kFrames; ++k) {
    tops::RoadIn in("in");
    tops::RoadOut o("out");
    tops::RoadLines l("lines");
    write_frame(in, c.disparity, k);
    scw_road_top(in, o, l, c.setup.road, kN);
    drain(o, out);
    drain(l, lines);
  }
  CHECK(out == frames_of(c.road));
  REQUIRE(lines.size() == static_cast<std::size_t>(kFrames));
  CHECK(lines.back() != c.setup.road.nominal);  // the fit moved the road
}

TEST_CASE("C-synthesis top scw_ground_top gives what the chain's ground filter left",
          "[pipeline][hls]") {
  const auto& c = chain_run();
  std::vector<Build::ground::out_beat> out;
  for (int k = 0; k < kFrames; ++k) {
    tops::GroundIn in("in");
    tops::GroundOut o("out");
    write_frame(in, c.road, k);
    scw_ground_top(in, o, *c.setup.ground, kN);
    drain(o, out);
  }
  CHECK(out == frames_of(c.ground));
  CHECK(frames_of(c.ground) != frames_of(c.road));  // the filter cleared some pixels
}

TEST_CASE("C-synthesis top scw_labelling_top gives the chain's object table", "[pipeline][hls]") {
  const auto& c = chain_run();
  std::vector<scw::hls::labelling::LabelPacket> out;
  for (int k = 0; k < kFrames; ++k) {
    tops::LabellingIn in("in");
    tops::Words o("objects");
    write_frame(in, c.ground, k);
    scw_labelling_top(in, o, c.setup.labelling_config(), 1);
    drain(o, out);
  }
  CHECK(out == c.objects);
  CHECK(out.size() > static_cast<std::size_t>(kFrames));  // objects, not status words alone
}

TEST_CASE("C-synthesis top scw_warning_top gives the chain's frame results", "[pipeline][hls]") {
  const auto& c = chain_run();
  // The road lines the warning stage measures heights on: the road stage's, by its frame function
  // (scw_road_top is another case's: its kernel is static).
  scw::hls::road::Road<Build::road> road(c.setup.road);
  scw::hls::Discard left_over;  // the beats: the road case's
  tops::RoadLines lines("lines");
  std::vector<scw::hls::warning::FrameResult> out;
  for (int k = 0; k < kFrames; ++k) {
    tops::RoadIn in("in");
    write_frame(in, c.disparity, k);
    scw::hls::road::road_frame(road, in, left_over, lines, kN);
    tops::Words words("objects");
    for (const auto& w : frame_words(c.objects, k)) words.write(w);
    tops::Results o("results");
    scw_warning_top(words, lines, o, c.setup.warning_config(), 1);
    CHECK(words.empty());
    while (!o.empty()) out.push_back(o.read().data);
  }
  CHECK(out == c.results);
  int decided = 0;  // frames an object decided (0xffff: none), so the results are not all empty
  for (const auto& r : out) decided += r.index != 0xffff ? 1 : 0;
  CHECK(decided >= 1);
}
