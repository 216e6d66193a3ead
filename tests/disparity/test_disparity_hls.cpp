// SPDX-License-Identifier: Apache-2.0
// The streaming disparity model against the direct reference (a fresh N x N SAD per pixel and
// candidate), pixel for pixel, on random images and on Tsukuba; frames back to back.
#include <catch2/catch.hpp>
#include <memory>
#include <opencv2/imgproc.hpp>

#include "host/io/tsukuba.hpp"
#include "host/reference/disparity_ref.hpp"
#include "sim/core/frame_beats.hpp"
#include "sim/models/disparity_model.hpp"
#include "tests/disparity/disparity_frames.hpp"

namespace {

using namespace scw;
using hls::disparity::DisparityConfig;

using Pair = test::StereoPair;
using test::random_pair;

/// Frames back to back through the model (no stalls); every output frame must equal the
/// reference of its own pair.
template <typename Params>
void check(const std::vector<Pair>& frames, int w, int h, const DisparityConfig& cfg,
           int num_disp = Params::kNumDisp) {
  const auto s = test::stereo_streams<typename Params::pixel_beat>(frames, w, h);
  const auto& l = s.left;
  const auto& r = s.right;
  auto model = std::make_unique<sim::DisparityModel<Params>>(cfg);
  const auto run = sim::run_join(*model, l, r, {}, l.size(), 100'000'000);
  REQUIRE_FALSE(run.timed_out);
  REQUIRE(run.violations.empty());
  CHECK_FALSE(model->kernel().error());
  const std::size_t per_frame = l.size() / frames.size();
  for (std::size_t f = 0; f < frames.size(); ++f) {
    const auto ref = reference::disparity_reference(frames[f].left.data(), frames[f].right.data(),
                                                    w, h, Params::kWindow, num_disp, cfg);
    std::vector<std::uint16_t> got;
    for (std::size_t i = f * per_frame; i < (f + 1) * per_frame; ++i)
      got.insert(got.end(), run.out[i].px.begin(), run.out[i].px.end());
    std::size_t diff = 0;
    for (std::size_t i = 0; i < got.size(); ++i) diff += got[i] != ref[i] ? 1 : 0;
    INFO("frame " << f << ": " << diff << " of " << got.size() << " pixels differ");
    CHECK(diff == 0);
  }
}

Pair tsukuba(int x, int y, int w, int h) {
  const auto [l, r] = scw::host::io::read_tsukuba_pair(SCW_DATA_DIR "/tsukuba");
  const cv::Rect roi(x, y, w, h);
  const cv::Mat lc = l(roi).clone(), rc = r(roi).clone();
  return {std::vector<std::uint8_t>(lc.datastart, lc.dataend),
          std::vector<std::uint8_t>(rc.datastart, rc.dataend)};
}

}  // namespace

TEST_CASE("disparity model equals the direct reference (thesis mode)", "[disparity][hls]") {
  SECTION("P = 1, N = 5, d 2..9, random pairs") {
    auto cfg = hls::disparity::thesis_mode(64, 24, 2);
    check<hls::disparity::DisparityParams<1, 64, 5, 8>>(
        {random_pair(64, 24, 2, 8, 1), random_pair(64, 24, 2, 8, 2), random_pair(64, 24, 2, 8, 3)},
        64, 24, cfg);
  }
  SECTION("P = 2, N = 7, d 0..15, SAD limit and uniqueness") {
    auto cfg = hls::disparity::thesis_mode(96, 32, 0);
    cfg.sad_limit = 2500;
    cfg.uniqueness_ratio = 15;
    check<hls::disparity::DisparityParams<2, 96, 7, 16>>(
        {random_pair(96, 32, 0, 16, 4), random_pair(96, 32, 0, 16, 5)}, 96, 32, cfg);
  }
  SECTION("P = 4, N = 9, d 3..18") {
    auto cfg = hls::disparity::thesis_mode(80, 28, 3);
    check<hls::disparity::DisparityParams<4, 80, 9, 16>>({random_pair(80, 28, 3, 16, 6)}, 80, 28,
                                                         cfg);
  }
  SECTION("the thesis's (21, 20, 64), P = 1 and P = 2, random and a Tsukuba crop") {
    auto cfg = hls::disparity::thesis_mode(128, 40, 20);
    check<hls::disparity::DisparityParams<1, 128, 21, 45>>(
        {random_pair(128, 40, 20, 45, 7), tsukuba(100, 100, 128, 40)}, 128, 40, cfg);
    check<hls::disparity::DisparityParams<2, 128, 21, 45>>({random_pair(128, 40, 20, 45, 8)}, 128,
                                                           40, cfg);
  }
  SECTION("Tsukuba, whole image, N = 9 and 15, d 0..15") {
    const Pair t = tsukuba(0, 0, 384, 288);
    check<hls::disparity::DisparityParams<2, 384, 9, 16>>({t}, 384, 288,
                                                          hls::disparity::thesis_mode(384, 288, 0));
    check<hls::disparity::DisparityParams<1, 384, 15, 16>>({t}, 384, 288,
                                                           hls::disparity::thesis_mode(384, 288, 0));
  }
}

TEST_CASE("disparity model equals the direct reference (opencv mode)", "[disparity][hls]") {
  SECTION("P = 1, N = 5, d 0..15, random pairs, odd height") {
    check<hls::disparity::DisparityParams<1, 64, 5, 16>>(
        {random_pair(64, 25, 0, 16, 11), random_pair(64, 25, 0, 16, 12)}, 64, 25,
        hls::disparity::opencv_mode(64, 25, 0));
  }
  SECTION("P = 2, N = 9, d 4..19, cap 63, texture 30, uniqueness 5") {
    check<hls::disparity::DisparityParams<2, 96, 9, 16>>(
        {random_pair(96, 32, 4, 16, 13), random_pair(96, 32, 4, 16, 14)}, 96, 32,
        hls::disparity::opencv_mode(96, 32, 4, 63, 30, 5));
  }
  SECTION("P = 4, N = 7, d 1..16") {
    check<hls::disparity::DisparityParams<4, 80, 7, 16>>({random_pair(80, 27, 1, 16, 15)}, 80, 27,
                                                         hls::disparity::opencv_mode(80, 27, 1));
  }
  SECTION("Tsukuba, whole image, N = 9 and 21, d 0..15, and the thesis's (21, 20, 64) on a crop") {
    const Pair t = tsukuba(0, 0, 384, 288);
    check<hls::disparity::DisparityParams<2, 384, 9, 16>>({t}, 384, 288,
                                                          hls::disparity::opencv_mode(384, 288, 0));
    check<hls::disparity::DisparityParams<1, 384, 21, 16>>(
        {t}, 384, 288, hls::disparity::opencv_mode(384, 288, 0));
    check<hls::disparity::DisparityParams<1, 128, 21, 45>>(
        {tsukuba(100, 100, 128, 40), random_pair(128, 40, 20, 45, 16)}, 128, 40,
        hls::disparity::opencv_mode(128, 40, 20));
  }
}

TEST_CASE("disparity model with fewer candidates than built equals the reference",
          "[disparity][hls]") {
  // A stage built for 16 candidates run on 11 (DisparityConfig::num_disp) must give exactly the
  // 11-candidate result: winner, uniqueness, sub-pixel ends and valid region all follow it.
  using Params = hls::disparity::DisparityParams<2, 96, 7, 16>;
  constexpr int kUsed = 11;
  const auto frames = std::vector<Pair>{random_pair(96, 30, 3, kUsed, 21), tsukuba(60, 80, 96, 30)};
  for (const bool opencv : {false, true}) {
    DYNAMIC_SECTION((opencv ? "opencv mode" : "thesis mode")) {
      auto cfg = opencv ? hls::disparity::opencv_mode(96, 30, 3)
                        : hls::disparity::thesis_mode(96, 30, 3);
      cfg.num_disp = kUsed;
      check<Params>(frames, 96, 30, cfg, kUsed);
    }
  }
}

TEST_CASE("disparity runs one beat per clock across frames", "[disparity][hls][cycles]") {
  // Exact cycle counts: K frames back to back are taken in K * H * W/P cycles, one pair of beats
  // per clock, and the output ends when the reader has emitted what follows the last computed
  // pixel: the rest of its row (ceil(R/P) beats) and the bottom R rows (invalid codes, emitted
  // without input), after the core's latency, the output register and the cycle that takes the
  // last beat. No cycle is lost between frames: the bottom rows of a frame leave while the next
  // frame comes in.
  using Params = hls::disparity::DisparityParams<2, 64, 7, 8>;
  constexpr int W = 64, H = 20, K = 3, R = Params::kRadius, P = Params::kPpc;
  std::vector<Pair> frames;
  for (int f = 0; f < K; ++f) frames.push_back(random_pair(W, H, 1, 8, 40 + f));
  const auto s = test::stereo_streams<Params::pixel_beat>(frames, W, H);
  const auto& l = s.left;
  const auto& r = s.right;
  // The prefilter (opencv mode) delays the core by two rows: its output row v needs input row
  // v + 1 complete, so it leaves while input row v + 2 comes in.
  for (const bool opencv : {false, true}) {
    DYNAMIC_SECTION((opencv ? "opencv mode" : "thesis mode")) {
      sim::DisparityModel<Params> model(opencv ? hls::disparity::opencv_mode(W, H, 1)
                                               : hls::disparity::thesis_mode(W, H, 1));
      const auto run = sim::run_join(model, l, r, {}, l.size());
      REQUIRE_FALSE(run.timed_out);
      std::int64_t last_take = -1;
      for (std::size_t c = 0; c < run.trace.size(); ++c)
        if (run.trace[c].in_valid && run.trace[c].in_ready) last_take = static_cast<std::int64_t>(c);
      CHECK(last_take == K * H * W / P - 1);
      CHECK(run.cycles ==
            K * H * W / P + (R + (opencv ? 2 : 0)) * W / P + (R + P - 1) / P + 1 +
                hls::disparity::Disparity<Params>::kLatency);
    }
  }
}

namespace {

/// The frame function (the stage's HLS top) over `frames` back to back against the clocked
/// model's output under no stalls.
template <typename Params>
void check_frame_function(const std::vector<Pair>& frames, int w, int h,
                          const DisparityConfig& cfg) {
  const auto s = test::stereo_streams<typename Params::pixel_beat>(frames, w, h);
  auto model = std::make_unique<sim::DisparityModel<Params>>(cfg);
  const auto run = sim::run_join(*model, s.left, s.right, {}, s.left.size(), 100'000'000);
  REQUIRE_FALSE(run.timed_out);
  auto k = std::make_unique<hls::disparity::Disparity<Params>>(cfg);
  const int n = static_cast<int>(s.left.size());
  std::vector<typename Params::disp_beat> out(s.left.size());
  CHECK(hls::disparity::disparity_frame(*k, s.left.data(), s.right.data(), out.data(), n,
                                        100'000'000) == n);
  CHECK(out == run.out);
  CHECK_FALSE(k->error());
}

}  // namespace

TEST_CASE("the frame function (the HLS top) equals the clocked model", "[disparity][hls]") {
  check_frame_function<hls::disparity::DisparityParams<1, 64, 5, 16>>(
      {random_pair(64, 25, 0, 16, 21), random_pair(64, 25, 0, 16, 22)}, 64, 25,
      hls::disparity::opencv_mode(64, 25, 0));
  check_frame_function<hls::disparity::DisparityParams<2, 96, 9, 16>>(
      {random_pair(96, 32, 4, 16, 23)}, 96, 32, DisparityConfig{96, 32, 4});
}
