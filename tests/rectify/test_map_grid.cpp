// SPDX-License-Identifier: Apache-2.0
// Grid-compressed maps: the expander kernel against the host's expand() bit for bit, the RTL
// against the kernel cycle for cycle under every stall pattern, expanded maps through the
// rectify model, and the chessboard calibration's error at G = 8, 16, 32.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <functional>
#include <opencv2/imgcodecs.hpp>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

#include "hls/rectify/map_grid.hpp"
#include "host/rectify/calibration.hpp"
#include "host/rectify/fixed_map.hpp"
#include "host/rectify/map_grid.hpp"
#include "host/rectify/run_model.hpp"
#include "host/reference/rectify_ref.hpp"
#include "sim/core/components.hpp"
#include "sim/core/join.hpp"
#include "sim/models/map_grid_model.hpp"
#include "sim/models/rectify_model.hpp"
#include "sim/rtl/map_grid_rtl.hpp"
#include "tests/common/primitive_configs.hpp"
#include "tests/common/twin_check.hpp"
#include "tests/rectify/random_maps.hpp"
#include "Vmap_grid_p1.h"
#include "Vmap_grid_p1_scw_rectify_map_grid.h"
#include "Vmap_grid_p2.h"
#include "Vmap_grid_p2_scw_rectify_map_grid.h"
#include "Vmap_grid_p4.h"
#include "Vmap_grid_p4_scw_rectify_map_grid.h"

namespace {

using namespace scw;
using hls::rectify::KnotPoint;
using hls::rectify::MapGridConfig;
using hls::rectify::MapGridParams;
using rectify::KnotGrid;

// Small Verilated configurations: the one source tests/CMakeLists.txt must match.
using GridP1 = MapGridParams<1, 32, 16, 2>;  // G = 4
using GridP2 = MapGridParams<2, 32, 16, 3>;  // G = 8
using GridP4 = MapGridParams<4, 32, 16, 2>;  // G = 4
static_assert(sim::map_grid_params_match<Vmap_grid_p1_scw_rectify_map_grid, GridP1>());
static_assert(sim::map_grid_params_match<Vmap_grid_p2_scw_rectify_map_grid, GridP2>());
static_assert(sim::map_grid_params_match<Vmap_grid_p4_scw_rectify_map_grid, GridP4>());
// The expander's beats are exactly the map beats of a rectify stage of the same size.
static_assert(
    std::is_same_v<GridP2::map_beat, hls::rectify::RectifyParams<2, 32, 16, 8>::map_beat>);
static_assert(std::is_same_v<MapGridParams<1, 1280, 480, 4>::map_beat,
                             hls::rectify::RectifyParams<1, 1280, 480, 128>::map_beat>);
static_assert(MapGridParams<1, 1280, 480, 4>::kKnotBits == 20);

/// Random knots for a width x height image: mostly a smooth warp with jitter (the realistic
/// case), some anywhere in the signed knot range (exercises every bit of the blends, the
/// rounding ties and both clamps).
template <typename Params>
KnotGrid random_knots(int width, int height, std::uint64_t seed, double wild = 0.15) {
  std::mt19937_64 rng(seed);
  const auto uni = [&](double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(rng);
  };
  KnotGrid g;
  g.width = width;
  g.height = height;
  g.grid_log2 = Params::kGridLog2;
  g.frac_bits = Params::kFracBits;
  g.knot_frac_bits = Params::kKnotFracBits;
  g.knot_bits = Params::kKnotBits;
  g.cols = rectify::knot_count(width, g.grid_log2);
  g.rows = rectify::knot_count(height, g.grid_log2);
  const double fk = std::ldexp(1.0, Params::kKnotFracBits);
  const std::int64_t lim = std::int64_t{1} << (Params::kKnotBits - 1);
  const double angle = uni(-0.1, 0.1), dx = uni(-3, 3), dy = uni(-3, 3);
  for (int j = 0; j < g.rows; ++j)
    for (int i = 0; i < g.cols; ++i) {
      const double u = i * g.grid(), v = j * g.grid();
      KnotPoint k;
      if (uni(0, 1) < wild) {
        k.x = static_cast<std::int32_t>(static_cast<std::int64_t>(rng() % (2 * lim)) - lim);
        k.y = static_cast<std::int32_t>(static_cast<std::int64_t>(rng() % (2 * lim)) - lim);
      } else {
        const double x = u * std::cos(angle) - v * std::sin(angle) + dx + uni(-0.7, 0.7);
        const double y = u * std::sin(angle) + v * std::cos(angle) + dy + uni(-0.7, 0.7);
        k.x = static_cast<std::int32_t>(std::lround(x * fk));
        k.y = static_cast<std::int32_t>(std::lround(y * fk));
      }
      g.knots.push_back(k);
    }
  return g;
}

/// The host's expanded map of `g` as map beats, `frames` times.
template <typename Params>
std::vector<typename Params::map_beat> expected_beats(const KnotGrid& g, int frames) {
  const auto m = rectify::expand(g);
  const auto one =
      sim::frame_beats_of<typename Params::map_beat>(m.points.data(), m.width, m.height);
  std::vector<typename Params::map_beat> all;
  for (int f = 0; f < frames; ++f) all.insert(all.end(), one.begin(), one.end());
  return all;
}

template <typename Params>
void check_kernel(int width, int height, std::uint64_t seed) {
  INFO("P = " << Params::kPpc << ", G = " << Params::kGrid << ", " << width << " x " << height
              << ", seed " << seed);
  const KnotGrid g = random_knots<Params>(width, height, seed);
  hls::rectify::MapGrid<Params> k(MapGridConfig{width, height});
  for (int j = 0; j < g.rows; ++j)
    for (int i = 0; i < g.cols; ++i) k.write_knot(i, j, g.at(i, j));
  const auto expected = expected_beats<Params>(g, 2);
  std::vector<typename Params::map_beat> got;
  for (std::size_t n = 0; n < expected.size(); ++n) got.push_back(k.step());
  CHECK(got == expected);
}

}  // namespace

TEST_CASE("the grid expander equals the host's expand() bit for bit on random knots",
          "[rectify][hls][grid]") {
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    check_kernel<MapGridParams<1, 64, 32, 1>>(64, 32, seed);  // G = 2, the shortest shift
    check_kernel<MapGridParams<1, 64, 32, 2>>(62, 31, seed);  // W, H not multiples of G
    check_kernel<MapGridParams<2, 96, 64, 3>>(90, 50, seed);
    check_kernel<MapGridParams<4, 128, 64, 2>>(128, 64, seed);  // G = P
    check_kernel<MapGridParams<4, 160, 96, 4>>(156, 93, seed);
    check_kernel<MapGridParams<2, 256, 128, 6>>(250, 100, seed);    // G = 64, widest blends
    check_kernel<MapGridParams<1, 64, 32, 3, 5, 5>>(64, 32, seed);  // knots at F bits
    check_kernel<MapGridParams<1, 64, 32, 3, 4, 9>>(60, 30, seed);  // F = 4, FK = F + 5
  }
  // Full size, every knot anywhere in the signed range.
  check_kernel<MapGridParams<1, 1280, 480, 4>>(1280, 480, 11);
  using Wild = MapGridParams<4, 1280, 480, 5>;
  const KnotGrid g = random_knots<Wild>(1280, 480, 12, 1.0);
  hls::rectify::MapGrid<Wild> k(MapGridConfig{1280, 480});
  for (int j = 0; j < g.rows; ++j)
    for (int i = 0; i < g.cols; ++i) k.write_knot(i, j, g.at(i, j));
  const auto expected = expected_beats<Wild>(g, 1);
  std::vector<Wild::map_beat> got;
  for (std::size_t n = 0; n < expected.size(); ++n) got.push_back(k.step());
  CHECK(got == expected);
}

namespace {

/// Loads `g` into both models, runs `frames` frames under `pattern`, and checks: handshake rules,
/// identical cycle traces, and (unless knots change mid-run) the host's expanded map.
template <typename VM, typename Params>
void run_twins(const KnotGrid& g, const sim::StallPattern& pattern, int frames,
               const std::function<void(std::int64_t, sim::KnotWrite&)>& mid_run = {}) {
  const MapGridConfig cfg{g.width, g.height};
  sim::MapGridModel<Params> cpp(cfg);
  sim::MapGridRtl<VM, Params> rtl("map_grid", cfg);
  const auto at = [&](int i, int j) { return g.at(i, j); };
  sim::load_knots(cpp, g.cols, g.rows, at);
  sim::load_knots(rtl, g.cols, g.rows, at);
  const auto expected = expected_beats<Params>(g, frames);
  const auto hook = [&](auto& model) {
    return [&](std::int64_t c, decltype(model)& m) {
      sim::KnotWrite w;
      if (mid_run) mid_run(c, w);
      m.drive_knot(w);
    };
  };
  const auto rc = sim::run_source<sim::MapGridModel<Params>>(cpp, pattern, expected.size(),
                                                             1'000'000, hook(cpp));
  const auto rr = sim::run_source<sim::MapGridRtl<VM, Params>>(rtl, pattern, expected.size(),
                                                               1'000'000, hook(rtl));
  test::check_twin_runs(rc, rr);
  if (!mid_run) CHECK(rr.out == expected);
}

template <typename VM, typename Params>
void check_rtl() {
  // The built size and a smaller one (fewer knot columns than the RAMs hold).
  const int sizes[][2] = {{Params::kMaxWidthPx, Params::kMaxHeight}, {24, 11}};
  std::uint64_t seed = 40;
  for (const auto& wh : sizes) {
    const KnotGrid g = random_knots<Params>(wh[0], wh[1], seed++);
    for (const auto& pattern : sim::StallPattern::all(3)) {
      DYNAMIC_SECTION(wh[0] << " x " << wh[1] << ", stalls " << pattern.name()) {
        run_twins<VM, Params>(g, pattern, 3);
      }
    }
  }
  SECTION("knots rewritten while frames stream") {
    // Same writes in the same cycles: the two must still agree cycle for cycle (the RAM read
    // at the issuing edge sees writes of earlier edges only, in both).
    const KnotGrid g = random_knots<Params>(Params::kMaxWidthPx, Params::kMaxHeight, 77);
    run_twins<VM, Params>(g, sim::StallPattern::parse("random:9"), 2,
                          [&](std::int64_t c, sim::KnotWrite& w) {
                            // A function of the cycle, so both runs see the same writes.
                            std::mt19937_64 rng(static_cast<std::uint64_t>(c) * 7919 + 78);
                            if (rng() % 3 != 0) return;
                            w.we = true;
                            w.col = static_cast<int>(rng() % static_cast<unsigned>(g.cols));
                            w.row = static_cast<int>(rng() % static_cast<unsigned>(g.rows));
                            w.knot = KnotPoint{static_cast<std::int32_t>(rng() % 4096) - 2048,
                                               static_cast<std::int32_t>(rng() % 4096) - 2048};
                          });
  }
}

}  // namespace

TEST_CASE("scw_rectify_map_grid equals the expander model cycle for cycle",
          "[rectify][rtl][grid]") {
  SECTION("P = 1, G = 4") { check_rtl<Vmap_grid_p1, GridP1>(); }
  SECTION("P = 2, G = 8") { check_rtl<Vmap_grid_p2, GridP2>(); }
  SECTION("P = 4, G = 4") { check_rtl<Vmap_grid_p4, GridP4>(); }
}

TEST_CASE("the expander issues one beat per clock, Latency cycles after run",
          "[rectify][rtl][grid]") {
  const KnotGrid g = random_knots<GridP2>(32, 16, 5);
  sim::MapGridRtl<Vmap_grid_p2, GridP2> rtl("map_grid", {32, 16});
  sim::load_knots(rtl, g.cols, g.rows, [&](int i, int j) { return g.at(i, j); });
  const std::size_t beats = 2 * 16 * 32 / 2;
  const auto r = sim::run_source(rtl, {}, beats);
  REQUIRE_FALSE(r.timed_out);
  CHECK(r.cycles == static_cast<std::int64_t>(beats) + GridP2::kLatency);
}

namespace {

/// Knots of a smooth warp (rotation by `deg` about the centre, shifted down by `down` rows) that
/// a rectify stage of 8 raw rows can serve.
template <typename Params>
KnotGrid warp_knots(int width, int height, double deg, double down) {
  KnotGrid g = random_knots<Params>(width, height, 1, 0.0);
  const double a = deg * std::acos(-1.0) / 180.0, cx = width / 2.0, cy = height / 2.0;
  const double fk = std::ldexp(1.0, Params::kKnotFracBits);
  for (int j = 0; j < g.rows; ++j)
    for (int i = 0; i < g.cols; ++i) {
      const double u = i * g.grid() - cx, v = j * g.grid() - cy;
      auto& k = g.knots[static_cast<std::size_t>(j * g.cols + i)];
      k.x = static_cast<std::int32_t>(std::lround((cx + u * std::cos(a) - v * std::sin(a)) * fk));
      k.y = static_cast<std::int32_t>(
          std::lround((cy + u * std::sin(a) + v * std::cos(a) + down) * fk));
    }
  return g;
}

}  // namespace

TEST_CASE("a grid-expanded map drives the rectify model to the reference rectification",
          "[rectify][pipeline][grid]") {
  // expander -> map FIFO -> rectify (C++ twins in sim/), raw frames from a source.
  using Grid = MapGridParams<2, 32, 16, 3>;
  using Rect = hls::rectify::RectifyParams<2, 32, 16, 8>;
  constexpr int W = 32, H = 16, D = 4, kFrames = 3;
  const KnotGrid g = warp_knots<Grid>(W, H, 3.0, 1.3);
  const auto map = rectify::expand(g);
  REQUIRE(test::map_in_window(map.points, W, H, Rect::kFracBits, D, Rect::kRows));
  std::vector<Rect::pixel_beat> raw_beats, expected;
  for (int f = 0; f < kFrames; ++f) {
    const auto img = test::random_image(W, H, 100 + static_cast<std::uint64_t>(f));
    const auto b = sim::frame_beats<2>(img.data(), W, H);
    raw_beats.insert(raw_beats.end(), b.begin(), b.end());
    const auto ref =
        reference::rectify_reference(img.data(), W, H, map.points.data(), W, H, Rect::kFracBits);
    const auto e = sim::frame_beats<2>(ref.data(), W, H);
    expected.insert(expected.end(), e.begin(), e.end());
  }
  for (const auto& pattern : {sim::StallPattern{}, sim::StallPattern::parse("random:3")}) {
    DYNAMIC_SECTION("stalls " << pattern.name()) {
      sim::Simulator s;
      auto& raw_q = s.fifo<Rect::pixel_beat>("raw", 4);
      auto& map_q = s.fifo<Rect::map_beat>("map", 4);
      auto& out_q = s.fifo<Rect::pixel_beat>("out", 4);
      sim::MapGridModel<Grid> grid(MapGridConfig{W, H});
      sim::load_knots(grid, g.cols, g.rows, [&](int i, int j) { return g.at(i, j); });
      s.add<sim::SourceModelComponent<sim::MapGridModel<Grid>>>("map_grid", grid, map_q);
      s.add<sim::Source<Rect::pixel_beat>>("camera", raw_q, raw_beats, pattern);
      s.add<sim::JoinComponent<sim::RectifyModel<Rect>>>(
          "rectify", sim::RectifyModel<Rect>({W, H, D}), raw_q, map_q, out_q);
      auto& sink = s.add<sim::Sink<Rect::pixel_beat>>("sink", out_q, pattern);
      s.run_until([&] { return sink.beats().size() >= expected.size(); }, 100'000);
      CHECK(sink.beats() == expected);
    }
  }
}

namespace {

const std::string kCalib =
    std::string(SCW_DATA_DIR) + "/chessboard/derived_stereo_calibration_helper.yml";

struct Chessboard {
  rectify::StereoCalibration calib = rectify::load_stereo_calibration(kCalib);
  rectify::StereoRectification rect = rectify::rectify_calibration(calib);
  rectify::FixedMap left = rectify::quantise_map(rect.map1_x, rect.map1_y);
  rectify::FixedMap right = rectify::quantise_map(rect.map2_x, rect.map2_y);
};
const Chessboard& chessboard() {
  static const Chessboard c;
  return c;
}

}  // namespace

TEST_CASE("chessboard: the expanded map stays within the curvature bound of the full map",
          "[rectify][host][grid]") {
  const auto& cb = chessboard();
  // Largest coordinate error (px) measured at G = 8, 16, 32, both cameras (docs/rectify.md):
  // 1, 2 and 7 steps of 1/32 px. The analytic bound (curvature, expansion_error_bound) is what
  // must hold; the measured values, plus one step for another OpenCV's float maps, catch a
  // regression in the knots or the expansion long before it reaches the bound.
  const double kMeasuredMax[] = {1 / 32.0, 2 / 32.0, 7 / 32.0};
  int n = 0;
  for (const int k : {3, 4, 5}) {
    const auto knots = rectify::grid_knots(cb.calib, cb.rect, k);
    for (const auto* side : {"left", "right"}) {
      const bool l = std::string(side) == "left";
      const KnotGrid& g = l ? knots.left : knots.right;
      const auto& full = l ? cb.left : cb.right;
      cv::Mat mx, my;
      if (l)
        rectify::extended_float_maps(cb.calib.M1, cb.calib.D1, cb.rect.R1, cb.rect.P1,
                                     cb.rect.image_size, k, mx, my);
      else
        rectify::extended_float_maps(cb.calib.M2, cb.calib.D2, cb.rect.R2, cb.rect.P2,
                                     cb.rect.image_size, k, mx, my);
      const auto e = rectify::map_error(rectify::expand(g), full);
      const double bx = rectify::expansion_error_bound(rectify::max_curvature(mx), k, 5, 7);
      const double by = rectify::expansion_error_bound(rectify::max_curvature(my), k, 5, 7);
      WARN("chessboard " << side << ", G = " << (1 << k) << ": " << g.cols << " x " << g.rows
                         << " knots, " << rectify::knot_storage_bits(640, 480, k, g.knot_bits)
                         << " bits; max |dx| " << e.max_dx << " px (bound " << bx << "), max |dy| "
                         << e.max_dy << " px (bound " << by << "), mean |dx| " << e.mean_dx
                         << ", mean |dy| " << e.mean_dy);
      CHECK(g.clamped == 0);
      CHECK(e.max_dx <= bx);
      CHECK(e.max_dy <= by);
      CHECK(e.max() <= kMeasuredMax[n] + 1 / 32.0);
    }
    ++n;
  }
}

TEST_CASE("chessboard: an expanded map rectifies through the model as the reference does",
          "[rectify][host][grid]") {
  const auto& cb = chessboard();
  const auto knots = rectify::grid_knots(cb.calib, cb.rect, 4);
  const auto map = rectify::expand(knots.left);
  const auto plan = rectify::plan_for_stage({rectify::row_window(map)}, rectify::kHostStageRows,
                                            "chessboard (G = 16)");
  const cv::Mat raw =
      cv::imread(std::string(SCW_DATA_DIR) + "/chessboard/left01.jpg", cv::IMREAD_GRAYSCALE);
  REQUIRE(!raw.empty());
  const cv::Mat ours = rectify::rectify_image(raw, map, plan.lead_rows);
  const auto ref = reference::rectify_reference(raw.data, raw.cols, raw.rows, map.points.data(),
                                                map.width, map.height, map.frac_bits);
  REQUIRE(ours.isContinuous());
  CHECK(std::vector<std::uint8_t>(ours.data, ours.data + ours.total()) == ref);
}
