// SPDX-License-Identifier: Apache-2.0
// The thesis-size build's Verilated blocks (scw_pipeline_build in sim/CMakeLists.txt), each checked
// against hls::pipeline::ThesisPipeline<P>, bundled for PipelineChain. P = 1 always; P = 2 and 4
// when SCW_THESIS_RTL_PPC has them.
#pragma once

#include <type_traits>

#include "Vthesis_ground.h"
#include "Vthesis_ground_scw_ground.h"
#include "Vthesis_merge.h"
#include "Vthesis_merge_scw_result_merge.h"
#include "Vthesis_warning.h"
#include "Vthesis_warning_scw_warning.h"
#include "hls/pipeline/pipeline_params.hpp"
#include "sim/pipeline/pipeline_chain.hpp"
#include "sim/pipeline/pipeline_top.hpp"
// Their whole state, for skipping the cycles in which they are still (Harness::settle): the
// stages idle between frames.
#include "Vthesis_merge__Syms.h"
#include "Vthesis_warning__Syms.h"
SCW_MODEL_STATE(Vthesis_merge)
SCW_MODEL_STATE(Vthesis_warning)
// One beat width's blocks: Vthesis_p<P>_{check, grid, rectify, disparity, labelling}.
#include "Vthesis_p1_check.h"
#include "Vthesis_p1_check_scw_frame_check.h"
#include "Vthesis_p1_disparity.h"
#include "Vthesis_p1_disparity_scw_disparity.h"
#include "Vthesis_p1_grid.h"
#include "Vthesis_p1_grid_scw_rectify_map_grid.h"
#include "Vthesis_p1_labelling.h"
#include "Vthesis_p1_labelling_scw_labelling.h"
#include "Vthesis_p1_rectify.h"
#include "Vthesis_p1_rectify_scw_rectify.h"
#include "Vthesis_p1_road.h"
#include "Vthesis_p1_road_scw_road.h"
#include "Vthesis_p1_top.h"
#include "Vthesis_p1_top_scw_pipeline.h"
#if SCW_THESIS_RTL_P2
#include "Vthesis_p2_check.h"
#include "Vthesis_p2_check_scw_frame_check.h"
#include "Vthesis_p2_disparity.h"
#include "Vthesis_p2_disparity_scw_disparity.h"
#include "Vthesis_p2_grid.h"
#include "Vthesis_p2_grid_scw_rectify_map_grid.h"
#include "Vthesis_p2_labelling.h"
#include "Vthesis_p2_labelling_scw_labelling.h"
#include "Vthesis_p2_rectify.h"
#include "Vthesis_p2_rectify_scw_rectify.h"
#include "Vthesis_p2_road.h"
#include "Vthesis_p2_road_scw_road.h"
#include "Vthesis_p2_top.h"
#include "Vthesis_p2_top_scw_pipeline.h"
#endif
#if SCW_THESIS_RTL_P4
#include "Vthesis_p4_check.h"
#include "Vthesis_p4_check_scw_frame_check.h"
#include "Vthesis_p4_disparity.h"
#include "Vthesis_p4_disparity_scw_disparity.h"
#include "Vthesis_p4_grid.h"
#include "Vthesis_p4_grid_scw_rectify_map_grid.h"
#include "Vthesis_p4_labelling.h"
#include "Vthesis_p4_labelling_scw_labelling.h"
#include "Vthesis_p4_rectify.h"
#include "Vthesis_p4_rectify_scw_rectify.h"
#include "Vthesis_p4_road.h"
#include "Vthesis_p4_road_scw_road.h"
#include "Vthesis_p4_top.h"
#include "Vthesis_p4_top_scw_pipeline.h"
#endif

namespace scw::sim::thesis_build {

template <int P>
using Build = hls::pipeline::ThesisPipeline<P>;

template <int P>
using Check = typename FrameCheckModel<P, Build<P>::kMaxWidthPx, Build<P>::kMaxHeight>::params;

/// The blocks of beat width P, each Verilated model checked against the build it stands for.
template <int P, typename VCheck, typename VGrid, typename VRectify, typename VDisparity,
          typename VLabelling, typename VRoad, typename VFCheck, typename VFGrid,
          typename VFRectify, typename VFDisparity, typename VFLabelling, typename VFRoad,
          typename VTop, typename VFTop>
struct Blocks {
  static_assert(frame_check_params_match<VFCheck, Check<P>>());
  static_assert(map_grid_params_match<VFGrid, typename Build<P>::map_grid>());
  static_assert(rectify_params_match<VFRectify, typename Build<P>::rectify>());
  static_assert(disparity_params_match<VFDisparity,
                                       hls::disparity::Disparity<typename Build<P>::disparity>>());
  static_assert(labelling_params_match<VFLabelling, typename Build<P>::labelling>());
  static_assert(road_params_match<VFRoad, typename Build<P>::road>());
  using type = PipelineRtl<VCheck, VGrid, VRectify, VDisparity, VLabelling, Vthesis_warning,
                           Vthesis_merge, std::conditional_t<P == 1, Vthesis_ground, void>,
                           VRoad>;
  static_assert(pipeline_params_match<VFTop, Build<P>>());
  using top = VTop;
};

static_assert(warning_params_match<Vthesis_warning_scw_warning, Build<1>::warning>());
static_assert(result_merge_params_match<Vthesis_merge_scw_result_merge>());
static_assert(ground_params_match<Vthesis_ground_scw_ground, Build<1>::ground>());

#define SCW_THESIS_BLOCKS(P)                                                                       \
  Blocks<P, Vthesis_p##P##_check, Vthesis_p##P##_grid, Vthesis_p##P##_rectify,                     \
         Vthesis_p##P##_disparity, Vthesis_p##P##_labelling, Vthesis_p##P##_road,                  \
         Vthesis_p##P##_check_scw_frame_check, Vthesis_p##P##_grid_scw_rectify_map_grid,           \
         Vthesis_p##P##_rectify_scw_rectify, Vthesis_p##P##_disparity_scw_disparity,               \
         Vthesis_p##P##_labelling_scw_labelling, Vthesis_p##P##_road_scw_road, Vthesis_p##P##_top, \
         Vthesis_p##P##_top_scw_pipeline>

template <int P>
struct Rtl;
template <>
struct Rtl<1> : SCW_THESIS_BLOCKS(1) {};
#if SCW_THESIS_RTL_P2
template <>
struct Rtl<2> : SCW_THESIS_BLOCKS(2) {};
#endif
#if SCW_THESIS_RTL_P4
template <>
struct Rtl<4> : SCW_THESIS_BLOCKS(4) {};
#endif
#undef SCW_THESIS_BLOCKS

/// The whole scw_pipeline top Verilated as one model at width P (`scw sim --engine rtl-top`).
template <int P>
using Top = PipelineTop<typename Rtl<P>::top, Build<P>>;

/// Whether this build Verilated width P: 1 always, 2 and 4 when SCW_THESIS_RTL_PPC names them.
template <int P>
inline constexpr bool kBuilt = P == 1
#if SCW_THESIS_RTL_P2
                               || P == 2
#endif
#if SCW_THESIS_RTL_P4
                               || P == 4
#endif
    ;

}  // namespace scw::sim::thesis_build
