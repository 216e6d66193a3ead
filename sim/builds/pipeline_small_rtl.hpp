// SPDX-License-Identifier: Apache-2.0
// The small build's Verilated blocks (scw_pipeline_build in sim/CMakeLists.txt), each checked
// against hls::pipeline::SmallPipeline<P>, bundled for PipelineChain and PipelineTop.
#pragma once

#include "hls/pipeline/pipeline_params.hpp"
#include "sim/pipeline/pipeline_chain.hpp"
#include "sim/pipeline/pipeline_top.hpp"
#include "Vpipe_ground.h"
#include "Vpipe_ground_scw_ground.h"
#include "Vpipe_merge.h"
#include "Vpipe_merge_scw_result_merge.h"
#include "Vpipe_p1_check.h"
#include "Vpipe_p1_check_scw_frame_check.h"
#include "Vpipe_p1_disparity.h"
#include "Vpipe_p1_disparity_scw_disparity.h"
#include "Vpipe_p1_grid.h"
#include "Vpipe_p1_grid_scw_rectify_map_grid.h"
#include "Vpipe_p1_labelling.h"
#include "Vpipe_p1_labelling_scw_labelling.h"
#include "Vpipe_p1_rectify.h"
#include "Vpipe_p1_rectify_scw_rectify.h"
#include "Vpipe_p1_road.h"
#include "Vpipe_p1_road_scw_road.h"
#include "Vpipe_p1_top.h"
#include "Vpipe_p1_top_scw_pipeline.h"
#include "Vpipe_p1_top_scw_pkg.h"
#include "Vpipe_p2_labelling.h"
#include "Vpipe_p2_labelling_scw_labelling.h"
#include "Vpipe_p2_road.h"
#include "Vpipe_p2_road_scw_road.h"
#include "Vpipe_p2_top.h"
#include "Vpipe_p2_top_scw_pipeline.h"
#include "Vpipe_warning.h"
#include "Vpipe_warning_scw_warning.h"
// Their whole state, for skipping the cycles in which they are still (Harness::settle): the
// stages idle between frames.
#include "Vpipe_merge__Syms.h"
#include "Vpipe_warning__Syms.h"
SCW_MODEL_STATE(Vpipe_merge)
SCW_MODEL_STATE(Vpipe_warning)

namespace scw::sim::small_build {

template <int P>
using Build = hls::pipeline::SmallPipeline<P>;

// Every Verilated model against the build it stands for.
static_assert(frame_check_params_match<
              Vpipe_p1_check_scw_frame_check,
              FrameCheckModel<1, Build<1>::kMaxWidthPx, Build<1>::kMaxHeight>::params>());
static_assert(map_grid_params_match<Vpipe_p1_grid_scw_rectify_map_grid,
                                              Build<1>::map_grid>());
static_assert(rectify_params_match<Vpipe_p1_rectify_scw_rectify, Build<1>::rectify>());
static_assert(disparity_params_match<Vpipe_p1_disparity_scw_disparity,
                                               hls::disparity::Disparity<Build<1>::disparity>>());
static_assert(labelling_params_match<Vpipe_p1_labelling_scw_labelling, Build<1>::labelling>());
static_assert(labelling_params_match<Vpipe_p2_labelling_scw_labelling, Build<2>::labelling>());
static_assert(road_params_match<Vpipe_p1_road_scw_road, Build<1>::road>());
static_assert(road_params_match<Vpipe_p2_road_scw_road, Build<2>::road>());
static_assert(warning_params_match<Vpipe_warning_scw_warning, Build<1>::warning>());
static_assert(result_merge_params_match<Vpipe_merge_scw_result_merge>());
static_assert(ground_params_match<Vpipe_ground_scw_ground, Build<1>::ground>());
static_assert(pipeline_params_match<Vpipe_p1_top_scw_pipeline, Build<1>>());
// The words between the stages: scw_pkg's widths, the one list the RTL takes them from, equal
// to the C++ packs'.
static_assert(Vpipe_p1_top_scw_pkg::ObjWordBits ==
              BeatLayout<hls::labelling::LabelPacket>::kPayloadBits);
static_assert(Vpipe_p1_top_scw_pkg::ResultWordBits ==
              BeatLayout<hls::warning::ResultPacket>::kPayloadBits);
static_assert(Vpipe_p1_top_scw_pkg::WarningCfgBits == warning_cfg::kBits);
static_assert(Vpipe_p1_top_scw_pkg::RoadCfgBits == road_cfg::kBits);
static_assert(Vpipe_p1_top_scw_pkg::DisparityCfgBits == disparity_cfg::kBits);
static_assert(Vpipe_p1_top_scw_pkg::LabellingCfgBits == labelling_cfg::kBits);
static_assert(Vpipe_p1_top_scw_pkg::PipeResultBits ==
              BeatLayout<hls::pipeline::PipelineResultPacket>::kPayloadBits);
static_assert(Vpipe_p1_top_scw_pkg::DispBits == 8 * sizeof(hls::road::disp_t));
static_assert(pipeline_params_match<Vpipe_p2_top_scw_pipeline, Build<2>>());

template <int P>
struct Rtl;
template <>
struct Rtl<1> {
  using type = PipelineRtl<Vpipe_p1_check, Vpipe_p1_grid, Vpipe_p1_rectify, Vpipe_p1_disparity,
                           Vpipe_p1_labelling, Vpipe_warning, Vpipe_merge, Vpipe_ground,
                           Vpipe_p1_road>;
  using top = Vpipe_p1_top;
};
template <>
struct Rtl<2> {
  // The blocks whose only difference at P = 2 is their width run in the top (PipelineTop).
  using type = PipelineRtl<void, void, void, void, Vpipe_p2_labelling, Vpipe_warning,
                           Vpipe_merge, void, Vpipe_p2_road>;
  using top = Vpipe_p2_top;
};

/// The blocks Verilated at P (the rest run as C++ in a chain; the top has them all).
template <int P>
PipelineEngines rtl_engines() {
  auto e = PipelineEngines::all(Engine::rtl);
  if (P != 1) e.check = e.map_grid = e.rectify = e.disparity = Engine::cpp;
  return e;
}

template <int P>
using Chain = PipelineChain<Build<P>, typename Rtl<P>::type>;
template <int P>
using Top = PipelineTop<typename Rtl<P>::top, Build<P>>;

}  // namespace scw::sim::small_build
