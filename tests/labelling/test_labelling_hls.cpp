// SPDX-License-Identifier: Apache-2.0
// [hls] The streaming labelling model against the flood-fill reference: random maps of many
// densities, adversarial shapes, every tile grid, Tsukuba's truth and a disparity-stage map;
// overflow and stream errors flagged with the next frame correct.
#include <algorithm>
#include <catch2/catch.hpp>
#include <memory>
#include <string>

#include "host/disparity/run_model.hpp"
#include "host/io/tsukuba.hpp"
#include "host/labelling/run_model.hpp"
#include "sim/models/labelling_model.hpp"
#include "tests/labelling/labelling_run.hpp"

namespace {

using namespace scw::test;
using scw::hls::labelling::LabellingParams;
using scw::labelling::grid_config;
using scw::sim::StallPattern;

// Room for every label a 64 x 48 map can need in one tile.
using Big = LabellingParams<64, 48, 8, 8, 1024, 4096>;

struct Grid {
  int tx, ty;
};
// 1 x 1, even grids, and grids whose tiles do not divide 64 x 48 (3 x 5, 7 x 5: 22 and 10 px).
const Grid kGrids[] = {{1, 1}, {2, 2}, {4, 3}, {8, 8}, {3, 5}, {7, 5}};

std::vector<FrameOut> run_model(const std::vector<DispMap>& maps, const LabellingConfig& cfg,
                                const StallPattern& p = {}) {
  auto m = std::make_unique<scw::sim::LabellingModel<Big>>(cfg);
  const auto r = run_maps(*m, maps, cfg, p);
  REQUIRE_FALSE(r.timed_out);
  CHECK(r.violations.empty());
  return split_frames(r.out);
}

std::vector<DispMap> random_maps() {
  std::vector<DispMap> v;
  std::uint64_t seed = 1;
  for (double density : {0.05, 0.2, 0.4, 0.55, 0.7, 0.85, 1.0})
    for (int k = 0; k < 2; ++k) v.push_back(random_map(64, 48, density, seed++));
  return v;
}

/// The second pass's label image (segment(), the host build) equals the reference's pixel for
/// pixel: the same pixel sets, numbered alike. segment() keeps its stage from one call of a
/// configuration to the next, so the maps of a loop go through one stage back to back.
void check_labels(const DispMap& m, const LabellingConfig& cfg) {
  cv::Mat d16(m.h, m.w, CV_16UC1);
  std::copy(m.d.begin(), m.d.end(), d16.ptr<std::uint16_t>());
  const auto ref = scw::reference::labelling_reference(m.d.data(), m.w, m.h, cfg);
  const auto s = scw::labelling::segment(d16, cfg);
  const cv::Mat ref_labels(m.h, m.w, CV_16UC1, const_cast<std::uint16_t*>(ref.labels.data()));
  CHECK(cv::countNonZero(s.labels != ref_labels) == 0);
}

}  // namespace

TEST_CASE("labelling model equals the flood fill on random maps, every grid", "[hls]") {
  const auto maps = random_maps();
  for (const Grid& g : kGrids) {
    for (int min_area : {1, 6}) {
      INFO("grid " << g.tx << " x " << g.ty << ", min area " << min_area);
      const auto cfg = grid_config(64, 48, g.tx, g.ty, 0, min_area);
      check_against_reference(run_model(maps, cfg), maps, cfg);
      for (const auto& m : maps) check_labels(m, cfg);
    }
  }
}

TEST_CASE("labelling model equals the flood fill on adversarial shapes, every grid", "[hls]") {
  auto maps = adversarial_maps(64, 48);
  maps.push_back(adversarial_maps(63, 47)[0]);  // an odd spiral (a different centre)
  for (const Grid& g : kGrids) {
    INFO("grid " << g.tx << " x " << g.ty);
    for (const auto& m : maps) {
      const auto cfg = grid_config(m.w, m.h, g.tx, g.ty, 0, 1);
      check_against_reference(run_model({m}, cfg), {m}, cfg);
      check_labels(m, cfg);
    }
  }
}

TEST_CASE("labelling model: the floor makes low disparities background", "[hls]") {
  const auto maps = random_maps();
  const auto cfg = grid_config(64, 48, 4, 3, 16 * 20, 1);
  check_against_reference(run_model(maps, cfg), maps, cfg);
}

TEST_CASE("labelling model: stalls change no object", "[hls]") {
  const std::vector<DispMap> maps{random_map(64, 48, 0.6, 99), spiral_map(64, 48)};
  const auto cfg = grid_config(64, 48, 3, 5, 0, 1);
  for (const auto& p : StallPattern::all(2)) {
    INFO(p.name());
    check_against_reference(run_model(maps, cfg, p), maps, cfg);
  }
}

namespace {

/// segment() (host build) against the reference on a whole map, several grids: objects and
/// the second pass's label image.
void check_segment(const cv::Mat& d16, int min_area, std::initializer_list<Grid> grids) {
  const auto ref = scw::reference::labelling_reference(d16.ptr<std::uint16_t>(), d16.cols,
                                                       d16.rows, grid_config(d16.cols, d16.rows,
                                                                             1, 1, 0, min_area));
  INFO(ref.objects.size() << " objects");
  CHECK(ref.objects.size() > 3);
  for (const Grid& g : grids) {
    INFO("grid " << g.tx << " x " << g.ty);
    const auto cfg = grid_config(d16.cols, d16.rows, g.tx, g.ty, 0, min_area);
    const auto s = scw::labelling::segment(d16, cfg);
    CHECK(s.objects_by_label == ref.objects);
    CHECK(s.status.objects == ref.objects.size());
    CHECK_FALSE(s.status.tile_overflow);
    const cv::Mat ref_labels(d16.rows, d16.cols, CV_16UC1,
                             const_cast<std::uint16_t*>(ref.labels.data()));
    CHECK(cv::countNonZero(s.labels != ref_labels) == 0);
  }
}

}  // namespace

TEST_CASE("labelling model equals the flood fill on Tsukuba's ground truth", "[hls]") {
  const cv::Mat d16 = scw::host::io::read_tsukuba_truth(SCW_DATA_DIR "/tsukuba", CV_16UC1);
  for (int min_area : {1, 50}) check_segment(d16, min_area, {{1, 1}, {4, 4}, {5, 3}, {8, 8}});
}

TEST_CASE("labelling model equals the flood fill on a disparity-stage map of Tsukuba", "[hls]") {
  const auto [l, r] = scw::host::io::read_tsukuba_pair(SCW_DATA_DIR "/tsukuba");
  const cv::Mat d = scw::disparity::disparity_image(
      l, r, 9, 0, 15, scw::disparity::mode_config(scw::disparity::Mode::thesis, l.cols, l.rows, 0));
  cv::Mat d16;
  d.convertTo(d16, CV_16U);  // thesis mode: invalid = 0, valid = d x 16 >= 0
  // Block matching's speckle needs more than the host's 2048 labels in a single 384 x 288
  // tile (1 x 1 is flagged as a tile overflow), so this map is cut into 2 x 2 and finer.
  for (int min_area : {1, 20}) check_segment(d16, min_area, {{2, 2}, {4, 4}, {5, 3}, {8, 8}});
}

TEST_CASE("labelling: a full label table is flagged and the next frame is correct", "[hls]") {
  // 2 x 2 tiles of 16 x 8 with 8 labels each: the dots map needs 16 per tile.
  using Small = LabellingParams<32, 16, 2, 2, 8, 64>;
  const auto cfg = grid_config(32, 16, 2, 2, 0, 1);
  const std::vector<DispMap> maps{dots_map(32, 16), spiral_map(32, 16), staircase_map(32, 16)};
  auto m = std::make_unique<scw::sim::LabellingModel<Small>>(cfg);
  const auto r = run_until_frames(*m, map_beats(maps), maps.size());
  const auto frames = split_frames(r.out);
  REQUIRE(frames.size() == 3);
  CHECK(frames[0].status.tile_overflow);
  CHECK(frames[0].status.objects == 4 * 8);  // each tile's first 8 dots
  const std::vector<DispMap> rest(maps.begin() + 1, maps.end());
  check_against_reference({frames[1], frames[2]}, rest, cfg);
}

TEST_CASE("labelling: more objects than MaxObjects are flagged, the next frame correct",
          "[hls]") {
  using Few = LabellingParams<32, 16, 2, 2, 64, 5>;
  const auto cfg = grid_config(32, 16, 2, 2, 0, 1);
  const std::vector<DispMap> maps{dots_map(32, 16), spiral_map(32, 16)};
  auto m = std::make_unique<scw::sim::LabellingModel<Few>>(cfg);
  const auto r = run_until_frames(*m, map_beats(maps), maps.size());
  const auto frames = split_frames(r.out);
  REQUIRE(frames.size() == 2);
  CHECK(frames[0].status.object_overflow);
  CHECK(frames[0].status.objects == 5);
  CHECK(frames[0].objects.size() == 5);
  check_against_reference({frames[1]}, {maps[1]}, cfg);
}

TEST_CASE("labelling: the next frame streams in while the objects of the last leave", "[hls]") {
  using Params = LabellingParams<32, 16, 2, 2, 64, 256>;  // room for the dots' 128 objects
  using Model = scw::sim::LabellingModel<Params>;
  const auto cfg = grid_config(32, 16, 2, 2, 0, 1);
  const std::vector<DispMap> maps{dots_map(32, 16), spiral_map(32, 16), staircase_map(32, 16)};
  check_emit_overlap<Model>([&] { return std::make_unique<Model>(cfg); }, maps, cfg);
}

TEST_CASE("labelling: broken frames are flagged and the next frame is correct", "[hls]") {
  check_broken_streams<LabellingParams<32, 16, 2, 2, 64, 64>>(grid_config(32, 16, 2, 2, 0, 1),
                                                              nested_u_map(32, 16), 100, 40);
}

namespace {

/// Whether v needs exactly `bits` bits: it fits, and would not fit in one fewer.
bool tight(std::uint64_t v, int bits) {
  return (bits >= 64 || (v >> bits) == 0) && (bits == 1 || (v >> (bits - 1)) != 0);
}

}  // namespace

TEST_CASE("labelling: the stored widths hold a full 1280 x 480 frame, and need every bit",
          "[hls]") {
  using scw::hls::labelling::desc_widths;
  using scw::hls::labelling::merge;
  using scw::hls::labelling::narrow;
  using scw::hls::labelling::pixel_object;
  constexpr int W = 1280, H = 480;
  constexpr auto w = desc_widths(W, H);
  // The bounds written beside the RTL's localparams (scw_labelling.sv).
  STATIC_REQUIRE(w.area == 20);
  STATIC_REQUIRE(w.x == 11);
  STATIC_REQUIRE(w.y == 9);
  STATIC_REQUIRE(w.sum_d == 35);
  STATIC_REQUIRE(w.sum_dd == 50);
  STATIC_REQUIRE(w.total() == 569);
  // The worst case of every sum: one object of every pixel (every term is non-negative, so no
  // pixel set has larger sums), at the largest disparity.
  Object all = pixel_object(0, 0, 0x7fff);
  for (int v = 0; v < H; ++v)
    for (int u = v == 0 ? 1 : 0; u < W; ++u) all = merge(all, pixel_object(u, v, 0x7fff));
  CHECK(narrow(all, w) == all);
  CHECK(tight(all.area, w.area));
  CHECK(tight(all.x_max, w.x));
  CHECK(tight(all.y_max, w.y));
  CHECK(tight(all.d_max, w.d));
  CHECK(tight(all.sum_d, w.sum_d));
  CHECK(tight(all.sum_dd, w.sum_dd));
  const std::uint64_t m[9] = {all.m10, all.m01, all.m20, all.m11, all.m02,
                              all.m30, all.m21, all.m12, all.m03};
  for (int i = 0; i < 9; ++i) {
    INFO("moment " << i);
    CHECK(tight(m[i], w.m[i]));
  }
  // The far corner alone: its coordinates are the largest a field holds.
  const Object corner = pixel_object(W - 1, H - 1, 0x7fff);
  CHECK(narrow(corner, w) == corner);
  // The stage's model through a whole full frame at this size: one object, every bit kept.
  using Thesis1 = LabellingParams<W, H, 8, 4, 32, 16>;
  STATIC_REQUIRE(Thesis1::kWidths.total() == 569);
  DispMap full{"full frame", W, H, std::vector<std::uint16_t>(static_cast<std::size_t>(W) * H, 0x7fff)};
  LabellingConfig cfg{W, H, W / 8, H / 4, 0, 1};
  auto model = std::make_unique<scw::sim::LabellingModel<Thesis1>>(cfg);
  const auto r = run_maps(*model, {full}, cfg, {});
  REQUIRE_FALSE(r.timed_out);
  const auto frames = split_frames(r.out);
  REQUIRE(frames.size() == 1);
  REQUIRE(frames[0].objects.size() == 1);
  CHECK(frames[0].objects[0] == all);
}

TEST_CASE("the frame function (the HLS top) equals the clocked model", "[hls]") {
  const std::vector<DispMap> maps{random_map(64, 48, 0.6, 5), spiral_map(64, 48),
                                  random_map(64, 48, 0.3, 6)};
  const auto cfg = grid_config(64, 48, 3, 5, 0, 1);
  auto m = std::make_unique<scw::sim::LabellingModel<Big>>(cfg);
  const auto r = run_maps(*m, maps, cfg, {});
  REQUIRE_FALSE(r.timed_out);
  const auto beats = map_beats<Big::in_beat>(maps);
  auto k = std::make_unique<scw::hls::labelling::Labelling<Big>>(cfg);
  std::vector<scw::hls::labelling::LabelPacket> out(r.out.size() + 8);
  const int written = scw::hls::labelling::labelling_frame(
      *k, beats.data(), static_cast<int>(beats.size()), out.data(), static_cast<int>(out.size()),
      static_cast<int>(maps.size()), 4'000'000);
  out.resize(static_cast<std::size_t>(written));
  CHECK(out == r.out);
  check_against_reference(split_frames(out), maps, cfg);
}
