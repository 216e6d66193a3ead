// SPDX-License-Identifier: Apache-2.0
// [rtl] scw_labelling against the labelling model clock for clock (the same cycle trace) under
// every stall pattern, both against the flood-fill reference, at one lane and at 2 and 4 lanes
// (pixels per beat); overflows and broken frames flagged with the next frame correct.
#include <catch2/catch.hpp>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "host/labelling/run_model.hpp"
#include "sim/models/labelling_model.hpp"
#include "sim/rtl/labelling_rtl.hpp"
#include "tests/common/twin_check.hpp"
#include "tests/labelling/labelling_run.hpp"
#include "Vlabelling_a.h"
#include "Vlabelling_a_scw_labelling.h"
#include "Vlabelling_b.h"
#include "Vlabelling_b_scw_labelling.h"
#include "Vlabelling_c.h"
#include "Vlabelling_c_scw_labelling.h"
#include "Vlabelling_l2.h"
#include "Vlabelling_l2_scw_labelling.h"
#include "Vlabelling_l4.h"
#include "Vlabelling_l4_scw_labelling.h"

namespace {

using namespace scw::test;
using scw::hls::labelling::LabellingParams;
using scw::labelling::grid_config;
using scw::sim::StallPattern;

// tests/labelling/rtl.cmake builds the same three with -G.
// A: 32 x 24, up to 4 x 4 tiles, with room for every random map's labels (2 x 2 tiles of
// 16 x 12 at density 0.7 need more than 64) and objects.
using ParamsA = LabellingParams<32, 24, 4, 4, 128, 256>;
// B: tables small enough to overflow: 8 labels per tile, 5 objects.
using ParamsB = LabellingParams<24, 16, 2, 2, 8, 5>;
// C: nothing a power of two (non-trivial node arithmetic): 3 x 3 tiles of 20 labels, room for
// a checkerboard's labels in a tile of 10 x 4 and for every random map's objects.
using ParamsC = LabellingParams<20, 12, 3, 3, 20, 100>;

static_assert(scw::sim::labelling_params_match<Vlabelling_a_scw_labelling, ParamsA>());
static_assert(scw::sim::labelling_params_match<Vlabelling_b_scw_labelling, ParamsB>());
// L2, L4: A's capacities at 2 and 4 pixels per beat, one lane per strip of tile columns.
using ParamsL2 = LabellingParams<32, 24, 4, 4, 128, 256, 2>;
using ParamsL4 = LabellingParams<32, 24, 4, 4, 128, 256, 4>;

static_assert(scw::sim::labelling_params_match<Vlabelling_c_scw_labelling, ParamsC>());
static_assert(scw::sim::labelling_params_match<Vlabelling_l2_scw_labelling, ParamsL2>());
static_assert(scw::sim::labelling_params_match<Vlabelling_l4_scw_labelling, ParamsL4>());

/// One run of each twin on the same beats.
struct TwinRun {
  std::vector<FrameOut> frames;  // the RTL's
  bool err_cpp = false, err_rtl = false;
};

/// The model and the RTL on `beats` under `pattern` until `frames_n` status words have left:
/// the same cycle trace and outputs (check_twin_runs); returns the RTL's frames.
template <typename VM, typename Params>
TwinRun run_twins(const std::vector<typename Params::in_beat>& beats, std::size_t frames_n,
                  const LabellingConfig& cfg, const StallPattern& pattern) {
  auto enough = [frames_n](const std::vector<LabelPacket>& out) {
    std::size_t n = 0;
    for (const auto& p : out) n += p.last ? 1 : 0;
    return n >= frames_n;
  };
  scw::sim::LabellingModel<Params> cpp(cfg);
  auto rtl = scw::sim::make_labelling_rtl<VM, Params>("labelling", cfg);
  const auto rc = scw::sim::run_stream_until(cpp, beats, pattern, enough, 400'000);
  const auto rr = scw::sim::run_stream_until(rtl, beats, pattern, enough, 400'000);
  check_twin_runs(rc, rr);
  return {split_frames(rr.out), cpp.kernel().error(), rtl.dut().err_o != 0};
}

/// `maps` back to back under every stall pattern: twins equal, frames equal the reference.
template <typename VM, typename Params>
void check_maps(const std::vector<DispMap>& maps, const LabellingConfig& cfg) {
  const auto beats = map_beats<typename Params::in_beat>(maps);
  for (const auto& pattern : StallPattern::all(3)) {
    INFO("stalls " << pattern.name());
    const auto r = run_twins<VM, Params>(beats, maps.size(), cfg, pattern);
    check_against_reference(r.frames, maps, cfg);
    CHECK_FALSE(r.err_cpp);
    CHECK_FALSE(r.err_rtl);
  }
}

std::vector<DispMap> random_maps(int w, int h, std::uint64_t seed) {
  std::vector<DispMap> v;
  for (double density : {0.05, 0.2, 0.4, 0.55, 0.7, 0.85, 1.0})
    v.push_back(random_map(w, h, density, seed++));
  return v;
}

struct Grid {
  int tx, ty;
};

}  // namespace

TEST_CASE("scw_labelling equals the model clock for clock on random maps, several grids",
          "[labelling][rtl]") {
  const auto maps = random_maps(32, 24, 11);
  // 4 x 4 tiles of 8 x 6, 2 x 2 of 16 x 12, and 3 x 4 of 11 x 6 (the last column 10 wide).
  for (const Grid& g : {Grid{4, 4}, Grid{2, 2}, Grid{3, 4}}) {
    for (int min_area : {1, 4}) {
      DYNAMIC_SECTION("grid " << g.tx << " x " << g.ty << ", min area " << min_area) {
        check_maps<Vlabelling_a, ParamsA>(maps, grid_config(32, 24, g.tx, g.ty, 0, min_area));
      }
    }
  }
  SECTION("a floor makes low disparities background") {
    check_maps<Vlabelling_a, ParamsA>(maps, grid_config(32, 24, 4, 3, 16 * 20, 1));
  }
}

TEST_CASE("scw_labelling equals the model clock for clock on adversarial shapes",
          "[labelling][rtl]") {
  auto maps = adversarial_maps(32, 24);
  maps.push_back(spiral_map(31, 23));  // an odd spiral: a different centre
  for (const Grid& g : {Grid{4, 4}, Grid{3, 2}}) {
    DYNAMIC_SECTION("grid " << g.tx << " x " << g.ty) {
      for (const auto& m : maps) {
        INFO("map " << m.name);
        check_maps<Vlabelling_a, ParamsA>({m}, grid_config(m.w, m.h, g.tx, g.ty, 0, 1));
      }
    }
  }
}

TEST_CASE("scw_labelling equals the model clock for clock when edges queue up",
          "[labelling][rtl]") {
  DispMap flat = blank_map("flat", 32, 24);
  for (auto& d : flat.d) d = 400;
  const DispMap dense = random_map(32, 24, 1.0, 77);
  SECTION("the last column a tile of its own: every row ends with the edge of the row before") {
    // Repeated edges are dropped, so the frame drains without waiting for the merge unit.
    check_maps<Vlabelling_a, ParamsA>({flat, dense}, LabellingConfig{32, 24, 31, 6, 0, 1});
  }
  SECTION("stripes that do not join sideways: the queue fills and the input waits") {
    // Each pixel of a tile row's first row joins the pixel above, in another tile: one edge
    // per pixel, and the merge unit takes at least 5 clocks per edge.
    DispMap stripes = blank_map("stripes", 32, 24);
    for (int y = 0; y < 24; ++y)
      for (int x = 0; x < 32; ++x) stripes.at(x, y) = x % 2 ? 480 : 160;
    check_maps<Vlabelling_a, ParamsA>({stripes, dense}, grid_config(32, 24, 4, 4, 0, 1));
  }
}

TEST_CASE("scw_labelling equals the model clock for clock with 3 x 3 tiles of 20 labels",
          "[labelling][rtl]") {
  auto maps = random_maps(20, 12, 31);
  for (const auto& m : adversarial_maps(20, 12)) maps.push_back(m);
  for (const Grid& g : {Grid{3, 3}, Grid{2, 3}}) {
    DYNAMIC_SECTION("grid " << g.tx << " x " << g.ty) {
      check_maps<Vlabelling_c, ParamsC>(maps, grid_config(20, 12, g.tx, g.ty, 0, 1));
    }
  }
}

TEST_CASE("scw_labelling flags full tables like the model, the next frame correct",
          "[labelling][rtl]") {
  const auto cfg = grid_config(24, 16, 2, 2, 0, 1);  // tiles of 12 x 8, 8 labels, 5 objects
  // Dots 4 apart: 6 per tile (the labels fit), 24 objects.
  DispMap sparse = blank_map("sparse dots", 24, 16);
  for (int y = 0; y < 16; y += 4)
    for (int x = 0; x < 24; x += 4) sparse.at(x, y) = 300;
  // One object across all four tiles each.
  const DispMap spiral = spiral_map(24, 16), stairs = staircase_map(24, 16);
  const std::vector<DispMap> maps{dots_map(24, 16), spiral, sparse, stairs};
  const auto beats = map_beats(maps);
  for (const auto& pattern : StallPattern::all(3)) {
    INFO("stalls " << pattern.name());
    const auto r = run_twins<Vlabelling_b, ParamsB>(beats, maps.size(), cfg, pattern);
    REQUIRE(r.frames.size() == 4);
    // dots: 12 per tile need 12 labels; each tile's first 8 are objects, 5 of them reported
    CHECK(r.frames[0].status.tile_overflow);
    CHECK(r.frames[0].status.object_overflow);
    CHECK(r.frames[0].status.objects == 5);
    CHECK(r.frames[0].objects.size() == 5);
    CHECK_FALSE(r.frames[2].status.tile_overflow);
    CHECK(r.frames[2].status.object_overflow);
    CHECK(r.frames[2].status.objects == 5);
    check_against_reference({r.frames[1], r.frames[3]}, {spiral, stairs}, cfg);
    CHECK_FALSE(r.err_cpp);
    CHECK_FALSE(r.err_rtl);
  }
}

TEST_CASE("scw_labelling flags broken frames like the model, the next frame correct",
          "[labelling][rtl]") {
  const auto cfg = grid_config(32, 24, 2, 2, 0, 1);
  const DispMap good = nested_u_map(32, 24);
  for (const auto& s : broken_streams<InBeat>(good, 100, 40)) {
    for (const auto& pattern : StallPattern::all(3)) {
      INFO(s.name << ", stalls " << pattern.name());
      auto r = run_twins<Vlabelling_a, ParamsA>(s.beats, 2, cfg, pattern);
      CHECK(r.err_cpp);
      CHECK(r.err_rtl);
      REQUIRE(r.frames.size() == 2);
      CHECK(r.frames[0].status.stream_error);
      if (s.first_whole)  // flagged on the frame they precede
        CHECK(raster_sorted(r.frames[0].objects) == raster_sorted(r.frames[1].objects));
      check_against_reference({r.frames.back()}, {good}, cfg);
    }
  }
}

TEST_CASE("scw_labelling with lanes equals the model clock for clock on random maps",
          "[labelling][rtl]") {
  const auto maps = random_maps(32, 24, 41);
  // 4 x 4 tiles of 8 x 6 and 4 x 3 of 8 x 8: one or two tile columns per lane.
  for (const Grid& g : {Grid{4, 4}, Grid{4, 3}}) {
    DYNAMIC_SECTION("grid " << g.tx << " x " << g.ty) {
      check_maps<Vlabelling_l2, ParamsL2>(maps, grid_config(32, 24, g.tx, g.ty, 0, 1));
      check_maps<Vlabelling_l4, ParamsL4>(maps, grid_config(32, 24, g.tx, g.ty, 0, 3));
    }
  }
  SECTION("two lanes of two tile columns: 2 x 2 tiles of 16 x 12") {
    check_maps<Vlabelling_l2, ParamsL2>(maps, grid_config(32, 24, 2, 2, 0, 1));
  }
  SECTION("the last strip narrower: 30 or 28 px in tiles of 8") {
    check_maps<Vlabelling_l2, ParamsL2>(random_maps(30, 24, 43),
                                        LabellingConfig{30, 24, 8, 6, 0, 1});
    check_maps<Vlabelling_l4, ParamsL4>(random_maps(28, 24, 47),
                                        LabellingConfig{28, 24, 8, 6, 0, 1});
  }
}

TEST_CASE("scw_labelling with lanes equals the model clock for clock on adversarial shapes",
          "[labelling][rtl]") {
  auto maps = adversarial_maps(32, 24);
  DispMap stripes = blank_map("stripes", 32, 24);  // every pixel an edge to the one above
  for (int y = 0; y < 24; ++y)
    for (int x = 0; x < 32; ++x) stripes.at(x, y) = x % 2 ? 480 : 160;
  maps.push_back(stripes);
  for (const auto& m : maps) {
    INFO("map " << m.name);
    check_maps<Vlabelling_l2, ParamsL2>({m}, grid_config(32, 24, 4, 4, 0, 1));
    check_maps<Vlabelling_l4, ParamsL4>({m}, grid_config(32, 24, 4, 2, 0, 1));
  }
}

TEST_CASE("scw_labelling with lanes flags broken frames like the model, the next frame correct",
          "[labelling][rtl]") {
  const auto cfg = grid_config(32, 24, 4, 2, 0, 1);
  const DispMap good = nested_u_map(32, 24);
  for (const auto& s : broken_streams<ParamsL4::in_beat>(good, 25, 3)) {
    for (const auto& pattern : StallPattern::all(3)) {
      INFO(s.name << ", stalls " << pattern.name());
      auto r = run_twins<Vlabelling_l4, ParamsL4>(s.beats, 2, cfg, pattern);
      CHECK(r.err_cpp);
      CHECK(r.err_rtl);
      REQUIRE(r.frames.size() == 2);
      CHECK(r.frames[0].status.stream_error);
      check_against_reference({r.frames.back()}, {good}, cfg);
    }
  }
}

namespace {

/// The overlap check on the model and the RTL: every cycle's handshake and words equal.
template <typename VM, typename Params>
void check_emit_overlap_twins(int w, int h, int tiles) {
  using Cpp = scw::sim::LabellingModel<Params>;
  using Rtl = scw::sim::LabellingRtl<VM, Params>;
  const auto cfg = grid_config(w, h, tiles, 2, 0, 1);
  const std::vector<DispMap> maps{dots_map(w, h), spiral_map(w, h), staircase_map(w, h)};
  const auto rc = check_emit_overlap<Cpp>([&] { return std::make_unique<Cpp>(cfg); }, maps, cfg);
  auto make_rtl = [&] {
    return std::make_unique<Rtl>(scw::sim::make_labelling_rtl<VM, Params>("labelling", cfg));
  };
  const auto rr = check_emit_overlap<Rtl>(make_rtl, maps, cfg);
  REQUIRE(rc.size() == rr.size());
  for (std::size_t i = 0; i < rc.size(); ++i) {
    REQUIRE(rc[i].trace.size() == rr[i].trace.size());
    for (std::size_t c = 0; c < rc[i].trace.size(); ++c) {
      const auto& a = rc[i].trace[c];
      const auto& b = rr[i].trace[c];
      INFO("run " << i << ", cycle " << c);
      REQUIRE(a.in_ready == b.in_ready);
      REQUIRE(a.out_valid == b.out_valid);
      if (a.out_valid) REQUIRE(a.out == b.out);
    }
  }
}

}  // namespace

TEST_CASE("scw_labelling sends the objects of a frame while the next streams in, like the model",
          "[labelling][rtl]") {
  check_emit_overlap_twins<Vlabelling_a, ParamsA>(32, 24, 2);
  check_emit_overlap_twins<Vlabelling_l4, ParamsL4>(32, 24, 4);
}
