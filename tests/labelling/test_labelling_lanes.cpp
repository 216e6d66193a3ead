// SPDX-License-Identifier: Apache-2.0
// [hls] The labelling stage with 2 and 4 lanes (pixels per beat): the same objects and status as
// the one-lane stage and the flood-fill reference, on random maps, adversarial
// shapes, every grid the lanes can split, under stalls and on Tsukuba; a beat every clock;
// broken frames flagged with the next frame correct; configurations the lanes cannot split
// refused by name.
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

template <int Lanes>
using Big = LabellingParams<64, 48, 8, 8, 1024, 4096, Lanes>;

struct Grid {
  int tx, ty;
};

/// Every map back to back through the stage with `Lanes` lanes: its frames, and the clock of
/// every output word.
template <int Lanes, int W = 64, int H = 48>
std::vector<FrameOut> run_lanes(const std::vector<DispMap>& maps, const LabellingConfig& cfg,
                                const StallPattern& p = {}) {
  using Params = LabellingParams<W, H, 8, 8, 1024, 4096, Lanes>;
  auto m = std::make_unique<scw::sim::LabellingModel<Params>>(cfg);
  const auto r = run_maps(*m, maps, cfg, p);
  REQUIRE_FALSE(r.timed_out);
  CHECK(r.violations.empty());
  return split_frames(r.out);
}

/// The lane stage's frames hold the one-lane stage's objects (each lane numbers its own nodes,
/// so they leave lane by lane: compared in raster order of their first pixels) and status, and
/// the flood fill's.
template <int Lanes>
void check_lanes(const std::vector<DispMap>& maps, const LabellingConfig& cfg,
                 const StallPattern& p = {}) {
  const auto one = run_lanes<1>(maps, cfg);
  const auto many = run_lanes<Lanes>(maps, cfg, p);
  REQUIRE(many.size() == one.size());
  for (std::size_t i = 0; i < one.size(); ++i) {
    INFO("map " << maps[i].name);
    CHECK(raster_sorted(many[i].objects) == raster_sorted(one[i].objects));
    CHECK(many[i].status == one[i].status);
  }
  check_against_reference(many, maps, cfg);
}

std::vector<DispMap> random_maps() {
  std::vector<DispMap> v;
  std::uint64_t seed = 11;
  for (double density : {0.05, 0.3, 0.55, 0.7, 0.85, 1.0})
    v.push_back(random_map(64, 48, density, seed++));
  return v;
}

}  // namespace

TEST_CASE("labelling lanes equal one lane and the flood fill on random maps", "[hls]") {
  const auto maps = random_maps();
  for (const Grid& g : {Grid{2, 2}, Grid{4, 3}, Grid{8, 8}, Grid{2, 5}}) {
    INFO("2 lanes, grid " << g.tx << " x " << g.ty);
    check_lanes<2>(maps, grid_config(64, 48, g.tx, g.ty, 0, 1));
  }
  for (const Grid& g : {Grid{4, 3}, Grid{8, 8}, Grid{4, 1}}) {
    for (int min_area : {1, 6}) {
      INFO("4 lanes, grid " << g.tx << " x " << g.ty << ", min area " << min_area);
      check_lanes<4>(maps, grid_config(64, 48, g.tx, g.ty, 0, min_area));
    }
  }
}

TEST_CASE("labelling lanes equal one lane on adversarial shapes", "[hls]") {
  // Spirals, combs and staircases cross the strip borders many times: their parts meet only
  // through the border sweep's edges.
  const auto maps = adversarial_maps(64, 48);
  for (const Grid& g : {Grid{4, 3}, Grid{8, 8}}) {
    INFO("grid " << g.tx << " x " << g.ty);
    const auto cfg = grid_config(64, 48, g.tx, g.ty, 0, 1);
    check_lanes<2>(maps, cfg);
    check_lanes<4>(maps, cfg);
  }
}

TEST_CASE("labelling lanes: stalls on either side change no word", "[hls]") {
  const std::vector<DispMap> maps{random_map(64, 48, 0.6, 99), spiral_map(64, 48)};
  const auto cfg = grid_config(64, 48, 4, 3, 0, 1);
  for (const auto& p : StallPattern::all(2)) {
    INFO(p.name());
    check_lanes<4>(maps, cfg, p);
  }
}

TEST_CASE("labelling lanes equal one lane on a disparity-stage map of Tsukuba", "[hls]") {
  const auto [l, r] = scw::host::io::read_tsukuba_pair(SCW_DATA_DIR "/tsukuba");
  const cv::Mat d = scw::disparity::disparity_image(
      l, r, 9, 0, 15, scw::disparity::mode_config(scw::disparity::Mode::thesis, l.cols, l.rows, 0));
  DispMap m{"tsukuba", d.cols, d.rows, {}};
  m.d.resize(static_cast<std::size_t>(d.cols) * d.rows);
  for (int y = 0; y < d.rows; ++y)
    for (int x = 0; x < d.cols; ++x)
      m.d[static_cast<std::size_t>(y) * d.cols + x] = static_cast<std::uint16_t>(d.at<short>(y, x));
  const auto cfg = grid_config(m.w, m.h, 8, 4, 0, 20);
  const auto one = run_lanes<1, 384, 288>({m}, cfg);
  const auto four = run_lanes<4, 384, 288>({m}, cfg);
  REQUIRE(one.size() == 1);
  REQUIRE(four.size() == 1);
  CHECK(one[0].objects.size() > 10);
  CHECK(raster_sorted(four[0].objects) == raster_sorted(one[0].objects));
  CHECK(four[0].status == one[0].status);
  check_against_reference(four, {m}, cfg);
}

TEST_CASE("labelling lanes take a beat every clock inside a frame", "[hls]") {
  // The strips' FIFOs absorb each strip's burst of beats: the input waits only while the
  // stage is between frames (its end-of-frame sweeps), never inside one.
  const std::vector<DispMap> maps{random_map(64, 48, 0.5, 5), random_map(64, 48, 0.5, 6)};
  const auto cfg = grid_config(64, 48, 4, 3, 0, 1);
  auto model = std::make_unique<scw::sim::LabellingModel<Big<4>>>(cfg);
  auto& m = *model;
  const auto beats = map_beats<Big<4>::in_beat>(maps);
  std::size_t next = 0;
  long long held_in_frame = 0, cycles = 0;
  bool in_frame = false;
  while (next < beats.size() && cycles < 100000) {
    const auto o = m.eval(true, beats[next], true);
    if (o.in_ready) {
      in_frame = !(beats[next].eol && next + 1 < beats.size() && beats[next + 1].sof) &&
                 next + 1 != beats.size();
      ++next;
    } else if (in_frame) {
      ++held_in_frame;
    }
    m.tick();
    ++cycles;
  }
  REQUIRE(next == beats.size());
  CHECK(held_in_frame == 0);
}

TEST_CASE("labelling lanes: broken frames are flagged and the next frame is correct", "[hls]") {
  check_broken_streams<LabellingParams<32, 16, 4, 2, 64, 64, 4>>(
      grid_config(32, 16, 4, 2, 0, 1), nested_u_map(32, 16), 37, 10);
}

TEST_CASE("labelling lanes refuse grids the lanes cannot split, by name", "[hls]") {
  using scw::hls::labelling::check_config;
  auto message = [](const LabellingConfig& cfg) {
    try {
      check_config<Big<4>>(cfg);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  CHECK(message(grid_config(64, 48, 4, 3, 0, 1)) == "accepted");
  CHECK_THAT(message(grid_config(64, 48, 3, 3, 0, 1)),
             Catch::Contains("3 tile columns do not split evenly over 4 lanes"));
  CHECK_THAT(message(grid_config(62, 48, 4, 3, 0, 1)),
             Catch::Contains("width 62 is not a whole number of beats"));
  // 60 px in 4 tiles of 15: strips of 15 px are not whole beats of 4.
  CHECK_THAT(message(grid_config(60, 48, 4, 3, 0, 1)), Catch::Contains("strips of 15 px"));
  // 64 px in tiles of 20 (4 columns, the last 4 px): strips of 20 px > the lanes' 16.
  LabellingConfig wide = grid_config(64, 48, 4, 3, 0, 1);
  wide.tile_w = 20;
  CHECK_THAT(message(wide), Catch::Contains("this build's lanes hold 16 px"));
}
