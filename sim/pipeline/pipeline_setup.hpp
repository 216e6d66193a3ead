// SPDX-License-Identifier: Apache-2.0
// What one pipeline run is set to (the top's cfg_* ports and knot RAMs), which blocks run as
// RTL, the FIFO depths, and the checks that turn a setup no stage can take into a clear error.
#pragma once

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "hls/disparity/disparity_params.hpp"
#include "hls/ground/ground_params.hpp"
#include "hls/labelling/labelling_params.hpp"
#include "hls/pipeline/pipeline_config.hpp"
#include "hls/rectify/map_grid.hpp"
#include "hls/rectify/rectify_params.hpp"
#include "hls/road/road_params.hpp"
#include "hls/warning/warning_params.hpp"

namespace scw::sim {

enum class Engine { cpp, rtl };

/// Which blocks run as Verilated RTL; the rest run as their C++ models.
struct PipelineEngines {
  Engine check = Engine::cpp;
  Engine map_grid = Engine::cpp;
  Engine rectify = Engine::cpp;
  Engine disparity = Engine::cpp;
  Engine labelling = Engine::cpp;
  Engine warning = Engine::cpp;
  Engine merge = Engine::cpp;
  Engine ground = Engine::cpp;  // when the setup has a ground filter
  Engine road = Engine::cpp;

  static PipelineEngines all(Engine e) { return {e, e, e, e, e, e, e, e, e}; }
};

/// Depths of the links (scw_pipeline's *FifoDepth parameters; the defaults are the top's).
/// The stages take one beat per clock, so two to four places suffice.
/// Seeds of the second input's and the second output's stall patterns (the right camera, the
/// object table), derived from the first's (StallPattern::other_stream) the same way by the
/// C++ chain and the Verilated top, so both stall alike.
inline constexpr std::uint64_t kRightInputSalt = 17;
inline constexpr std::uint64_t kObjectTableSalt = 29;

struct PipelineDepths {
  int raw = 2;   // input and checked pixels, per camera
  int map = 4;   // map-grid expander to rectifier
  int rect = 4;  // rectifier to disparity
  int disp = 4;  // disparity to road, road to labelling (and the ground filter's link)
  int obj = 2;   // object words
  int res = 2;   // frame results and pipeline results
  int flag = 4;  // per-frame input flags: frames in flight between input and result
  int line = 4;  // road lines: frames in flight between the road stage and the warning stage
};

/// One run's settings: the stages' (hls::pipeline::PipelineConfig, the top's cfg ports; width
/// and height are the frame's for every stage), and what the simulator adds around them.
struct PipelineSetup : hls::pipeline::PipelineConfig {
  /// Ground removal (thesis 6.2) between the disparity and labelling stages, at one pixel per
  /// beat only; absent: no filter, the graph of scw_pipeline.
  std::optional<hls::ground::GroundConfig> ground;
  int knot_cols = 0, knot_rows = 0;  // each camera's knot grid, row-major
  std::vector<hls::rectify::KnotPoint> left_knots, right_knots;
  PipelineDepths depths;
};

/// Throws std::invalid_argument naming the first setting the build cannot take.
template <typename Build>
void check_setup(const PipelineSetup& s) {
  const auto fail = [](const std::string& why) {
    throw std::invalid_argument("pipeline setup: " + why);
  };
  const std::string built = " (built for up to " + std::to_string(Build::kMaxWidthPx) + " x " +
                            std::to_string(Build::kMaxHeight) + " at " +
                            std::to_string(Build::kPpc) + " pixels per beat)";
  if (s.width < 1 || s.width > Build::kMaxWidthPx || s.width % Build::kPpc != 0)
    fail("width " + std::to_string(s.width) + " is not a multiple of P in 1 .. max" + built);
  if (s.height < 1 || s.height > Build::kMaxHeight)
    fail("height " + std::to_string(s.height) + " is outside 1 .. max" + built);
  if (s.lead_rows < 1 || s.lead_rows > Build::kRectRows - 2)
    fail("the rectifiers' lead of " + std::to_string(s.lead_rows) + " rows needs 1 .. " +
         std::to_string(Build::kRectRows - 2) + " (the build keeps " +
         std::to_string(Build::kRectRows) + " raw rows)");
  const int cols = ((s.width - 1) >> Build::kGridLog2) + 2;
  const int rows = ((s.height - 1) >> Build::kGridLog2) + 2;
  if (s.knot_cols != cols || s.knot_rows != rows)
    fail("the knot grid is " + std::to_string(s.knot_cols) + " x " + std::to_string(s.knot_rows) +
         ", a " + std::to_string(s.width) + " x " + std::to_string(s.height) +
         " frame at a knot every " + std::to_string(1 << Build::kGridLog2) + " px needs " +
         std::to_string(cols) + " x " + std::to_string(rows));
  const auto n = static_cast<std::size_t>(cols) * static_cast<std::size_t>(rows);
  if (s.left_knots.size() != n || s.right_knots.size() != n)
    fail("each camera needs " + std::to_string(n) + " knots (left has " +
         std::to_string(s.left_knots.size()) + ", right " + std::to_string(s.right_knots.size()) +
         ")");
  const auto& d = s.disparity;
  const int nd = hls::disparity::candidates<Build::kNumDisp>(d);
  if (d.dmin < 0 || d.dmin + nd > s.width)
    fail("disparities " + std::to_string(d.dmin) + " .. " + std::to_string(d.dmin + nd - 1) +
         " do not fit a " + std::to_string(s.width) + "-pixel row");
  if (d.num_disp > Build::kNumDisp)
    fail("num_disp " + std::to_string(d.num_disp) + " is more than the built " +
         std::to_string(Build::kNumDisp) + " candidates");
  if (s.height < Build::kWindow || s.width < Build::kWindow)
    fail("the frame is smaller than the " + std::to_string(Build::kWindow) + " x " +
         std::to_string(Build::kWindow) + " window");
  hls::road::check_config(s.road);
  if (s.ground) {
    if (Build::kPpc != 1)
      fail("the ground filter takes one pixel per beat: run it at --ppc 1, or without ground "
           "removal");
    hls::ground::check_config(*s.ground);
  }
  const PipelineDepths& q = s.depths;
  for (int depth : {q.raw, q.map, q.rect, q.disp, q.obj, q.res, q.flag})
    if (depth < 1) fail("every FIFO depth must be at least 1");
}

}  // namespace scw::sim
