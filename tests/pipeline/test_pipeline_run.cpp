// SPDX-License-Identifier: Apache-2.0
// [pipeline][app] `scw run --engine rtl`: the application chain with the stages as Verilated RTL
// gives the frame the C++ models give; a frame no build takes is refused with the builds named;
// `scw sim --rtl-stages` (some blocks Verilated) reports what the C++ chain does.
#include <catch2/catch.hpp>
#include <cstdint>
#include <opencv2/imgproc.hpp>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "host/app/run.hpp"
#include "host/disparity/run_model.hpp"
#include "host/io/tsukuba.hpp"
#include "host/pipeline/rtl_engine.hpp"
#include "host/pipeline/sim_run.hpp"

namespace {

scw::app::RunOptions crop_options() {
  scw::app::RunOptions o;
  o.window = 9;
  o.min_disp = 0;
  o.max_disp = 15;
  o.tiles_x = 2;
  o.tiles_y = 2;
  o.min_area = 60;
  o.warning.focal_px = 615.0;
  o.warning.baseline_m = 0.1;
  o.warning.cu_px = 63.5;
  o.warning.cv_px = 47.5;
  return o;
}

}  // namespace

TEST_CASE("run with the Verilated stages equals run with the C++ models on a Tsukuba crop",
          "[pipeline][app][rtl]") {
  const cv::Rect crop(128, 96, 128, 96);
  const auto pair = scw::host::io::read_tsukuba_pair(SCW_DATA_DIR "/tsukuba");
  const cv::Mat l = pair.left(crop).clone();
  const cv::Mat r = pair.right(crop).clone();
  const auto o = crop_options();
  scw::app::Runner cpp(o, std::nullopt);
  scw::app::Runner rtl(o, std::nullopt, scw::host::pipeline::make_rtl_engine(o, 128, 96));
  for (int frame = 0; frame < 2; ++frame) {
    const auto a = cpp.process(l, r);
    const auto b = rtl.process(l, r);  // throws if the RTL's objects or result differ
    CHECK(b.result == a.result);
    CHECK(cv::countNonZero(a.disparity != b.disparity) == 0);
    CHECK(cv::countNonZero(a.left != b.left) == 0);
    CHECK(b.segmentation.objects == a.segmentation.objects);
    CHECK(scw::app::frame_json(frame, b) == scw::app::frame_json(frame, a));
    CHECK(a.result.objects >= 2);
    CHECK_FALSE(b.input_error);
  }
}

namespace {

constexpr int kRoadW = 128, kRoadH = 96;

/// A rectified road: textured, its disparity growing 0.2 px a row below the horizon (row 30),
/// as a camera 1.2 m above a flat road with a 0.24 m baseline sees it; a box standing on it.
std::pair<cv::Mat, cv::Mat> road_pair(unsigned seed) {
  const int w = kRoadW, h = kRoadH;
  cv::theRNG().state = seed;
  cv::Mat tex(h, w + 32, CV_8U);
  cv::randu(tex, 0, 255);
  cv::GaussianBlur(tex, tex, cv::Size(3, 3), 0.8);
  cv::Mat l(h, w, CV_8U), r(h, w, CV_8U);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const bool box = x >= 50 && x < 80 && y >= 20 && y < 70;
      const double d = box ? 8.0 : y > 30 ? 0.2 * (y - 30) : 0.0;
      const double xs = x + 16 + d;  // right image: the texture shifted by d
      const int x0 = static_cast<int>(xs);
      const double f = xs - x0;
      l.at<std::uint8_t>(y, x) = tex.at<std::uint8_t>(y, x + 16);
      r.at<std::uint8_t>(y, x) = cv::saturate_cast<std::uint8_t>(
          (1 - f) * tex.at<std::uint8_t>(y, x0) + f * tex.at<std::uint8_t>(y, x0 + 1));
    }
  return {l, r};
}

}  // namespace

TEST_CASE("run --ground with the Verilated stages equals the C++ models on a road",
          "[pipeline][app][rtl]") {
  const int w = kRoadW, h = kRoadH;
  const auto [l, r] = road_pair(1);
  auto o = crop_options();
  o.warning.baseline_m = 0.24;
  o.camera_height_m = 1.2;
  o.ground = true;
  scw::app::Runner cpp(o, std::nullopt);
  scw::app::Runner rtl(o, std::nullopt, scw::host::pipeline::make_rtl_engine(o, w, h));
  const auto a = cpp.process(l, r);
  const auto b = rtl.process(l, r);  // throws if the RTL's objects or result differ
  CHECK(b.result == a.result);
  CHECK(cv::countNonZero(a.disparity != b.disparity) == 0);
  CHECK(scw::app::frame_json(0, b) == scw::app::frame_json(0, a));
  // The filter did remove road: without it the map has more valid pixels.
  o.ground = false;
  scw::app::Runner plain(o, std::nullopt);
  const auto c = plain.process(l, r);
  const int removed = cv::countNonZero(c.disparity > 0) - cv::countNonZero(a.disparity > 0);
  INFO("road pixels removed: " << removed);
  CHECK(removed > 1000);
}

TEST_CASE(
    "the road stage over a sequence: one Verilated chain for all pairs, on one thread or two, "
    "equals the C++ models",
    "[pipeline][app][rtl][road]") {
  // The nominal road's horizon is the principal point's row, 47.5; the road's is 30, within the
  // 3 degrees of pitch a fit may move it: from the second frame on the road is found and removed.
  auto o = crop_options();
  o.warning.baseline_m = 0.24;
  o.camera_height_m = 1.2;
  scw::app::Runner cpp(o, std::nullopt);
  scw::app::Runner rtl(o, std::nullopt, scw::host::pipeline::make_rtl_engine(o, kRoadW, kRoadH));
  scw::app::Runner rtl2(o, std::nullopt,
                        scw::host::pipeline::make_rtl_engine(o, kRoadW, kRoadH, {}, 2));
  o.road = false;
  scw::app::Runner plain(o, std::nullopt);
  std::vector<int> removed;
  for (unsigned frame = 0; frame < 3; ++frame) {
    const auto [l, r] = road_pair(10 + frame);
    const auto a = cpp.process(l, r);
    const auto b = rtl.process(l, r);  // throws if the RTL's road, objects or result differ
    const auto b2 = rtl2.process(l, r);
    CHECK(b.result == a.result);
    CHECK(cv::countNonZero(a.disparity != b.disparity) == 0);
    CHECK(cv::countNonZero(a.disparity != b2.disparity) == 0);
    CHECK(scw::app::frame_json(static_cast<int>(frame), b) ==
          scw::app::frame_json(static_cast<int>(frame), a));
    CHECK(scw::app::frame_json(static_cast<int>(frame), b2) ==
          scw::app::frame_json(static_cast<int>(frame), a));
    const auto c = plain.process(l, r);
    removed.push_back(cv::countNonZero(c.disparity > 0) - cv::countNonZero(a.disparity > 0));
  }
  INFO("road pixels removed per frame: " << removed[0] << ", " << removed[1] << ", "
                                         << removed[2]);
  CHECK(removed[1] > removed[0] + 1000);  // the fitted road, not the nominal one
  CHECK(removed[2] > 2000);
}

TEST_CASE("run --engine rtl refuses a frame no build takes and names the builds",
          "[pipeline][app]") {
  auto o = crop_options();
  CHECK_THROWS_WITH(scw::host::pipeline::make_rtl_engine(o, 384, 288),
                    Catch::Contains("384 x 288") && Catch::Contains("small: up to 128 x 96"));
  o.window = 11;  // no build has it
  CHECK_THROWS_WITH(scw::host::pipeline::make_rtl_engine(o, 128, 96),
                    Catch::Contains("window 11") && Catch::Contains("thesis"));
  CHECK_THROWS_WITH(scw::host::pipeline::make_rtl_engine(crop_options(), 128, 96, {}, 3),
                    Catch::Contains("--threads 3: use 1 or 2"));
}

TEST_CASE("sim with some blocks Verilated (--rtl-stages) reports what the C++ chain does",
          "[pipeline][sim][rtl]") {
  // The blocks are clock-for-clock twins, so a chain that mixes them must give every cycle,
  // busy span, FIFO figure and result of the all-C++ chain: only the engine's name differs.
  scw::host::pipeline::SimOptions o;
  o.config = "small";
  o.frames = 2;
  o.stalls = "random:3";
  std::ostringstream log;
  const auto cpp = scw::host::pipeline::run_sim(o, log);
  o.rtl_stages = {"rectify", "labelling", "warning"};
  const auto mixed = scw::host::pipeline::run_sim(o, log);
  CHECK(mixed.engine == "mixed (rtl: rectify,labelling,warning)");
  auto a = scw::host::pipeline::sim_json(cpp);
  auto b = scw::host::pipeline::sim_json(mixed);
  REQUIRE(a.at("cycles").get<std::int64_t>() > 0);
  a.erase("engine");
  b.erase("engine");
  CHECK(a.dump() == b.dump());

  o.engine = "rtl";
  CHECK_THROWS_WITH(scw::host::pipeline::run_sim(o, log),
                    Catch::Contains("--engine rtl already Verilates every block"));
  o.engine = "cpp";
  o.rtl_stages = {"rectify", "labeling"};
  CHECK_THROWS_WITH(scw::host::pipeline::run_sim(o, log),
                    Catch::Contains("--rtl-stages: no block 'labeling'") &&
                        Catch::Contains("labelling, warning"));
}
