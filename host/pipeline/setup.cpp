// SPDX-License-Identifier: Apache-2.0
// Pipeline run settings from user options (host/pipeline/setup.hpp).
#include "host/pipeline/setup.hpp"

#include <stdexcept>
#include <string>
#include <utility>

#include "host/labelling/run_model.hpp"

namespace scw::host::pipeline {

StageOptions small_build_options() {
  StageOptions o;
  o.mode = disparity::Mode::opencv;
  o.dmin = 0;
  o.num_disp = 16;
  o.tiles_x = 2;
  o.tiles_y = 2;
  o.min_area = 20;
  o.warning.focal_px = 100.0;
  o.warning.baseline_m = 0.2;
  return o;
}

std::vector<hls::rectify::KnotPoint> identity_knots(int width, int height, int grid_log2) {
  const int cols = rectify::knot_count(width, grid_log2);
  const int rows = rectify::knot_count(height, grid_log2);
  constexpr int kKnotFrac = 7;  // MapGridParams' default KnotFracBits (FracBits 5 + 2)
  std::vector<hls::rectify::KnotPoint> k;
  k.reserve(static_cast<std::size_t>(cols * rows));
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < cols; ++i)
      k.push_back({(i << grid_log2) << kKnotFrac, (j << grid_log2) << kKnotFrac});
  return k;
}

host::warning::WarningSetup warning_setup(int width, int height, const StageOptions& opt) {
  auto w = opt.warning;
  if (w.cu_px == 0.0 && w.cv_px == 0.0) {
    w.cu_px = 0.5 * (width - 1);
    w.cv_px = 0.5 * (height - 1);
  }
  w.d_limit_px = opt.dmin + opt.num_disp - 1;
  return w;
}

sim::PipelineSetup make_setup(int width, int height, int grid_log2, const StageOptions& opt,
                              std::vector<hls::rectify::KnotPoint> left_knots,
                              std::vector<hls::rectify::KnotPoint> right_knots, int lead_rows) {
  if (opt.num_disp < 1)
    throw std::invalid_argument("num_disp " + std::to_string(opt.num_disp) + ": need at least 1");
  sim::PipelineSetup s;
  s.width = width;
  s.height = height;
  s.lead_rows = lead_rows;
  s.disparity = disparity::mode_config(opt.mode, width, height, opt.dmin);
  s.disparity.num_disp = opt.num_disp;
  s.disparity.edge_candidates = opt.edge_candidates;
  const int invalid = static_cast<std::int16_t>(hls::disparity::invalid_code(s.disparity));
  s.labelling = labelling::grid_config(width, height, opt.tiles_x, opt.tiles_y,
                                       invalid > 0 ? invalid : 0, opt.min_area);
  const auto w = warning_setup(width, height, opt);
  s.warning = host::warning::to_fixed(w);
  // The road stage is always in the chain: it fits the road (the warning stage measures heights
  // above it) and removes it from the labelling's input only with opt.road.
  auto r = road::rig_setup(w.baseline_m, w.focal_px, w.cv_px, opt.camera_height_m,
                           opt.camera_pitch_deg);
  r.min_count = opt.road_min_count;
  r.enable = opt.road;
  s.road = road::to_fixed(r);
  s.knot_cols = rectify::knot_count(width, grid_log2);
  s.knot_rows = rectify::knot_count(height, grid_log2);
  s.left_knots = std::move(left_knots);
  s.right_knots = std::move(right_knots);
  return s;
}

}  // namespace scw::host::pipeline
