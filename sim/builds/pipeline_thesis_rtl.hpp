// SPDX-License-Identifier: Apache-2.0
// The thesis-size build's Verilated blocks (sim/builds/pipeline_thesis.cmake), each checked
// against hls::pipeline::ThesisPipeline<P>, bundled for PipelineChain.
#pragma once

#include <cstdint>

#include "Vthesis_ground.h"
#include "Vthesis_ground_scw_ground.h"
#include "Vthesis_labelling.h"
#include "Vthesis_labelling_scw_labelling.h"
#include "Vthesis_merge.h"
#include "Vthesis_merge_scw_result_merge.h"
#include "Vthesis_p1_check.h"
#include "Vthesis_p1_check_scw_frame_check.h"
#include "Vthesis_p1_disparity.h"
#include "Vthesis_p1_disparity_scw_disparity.h"
#include "Vthesis_p1_grid.h"
#include "Vthesis_p1_grid_scw_rectify_map_grid.h"
#include "Vthesis_p1_rectify.h"
#include "Vthesis_p1_rectify_scw_rectify.h"
#if SCW_THESIS_RTL_P2
#include "Vthesis_p2_check.h"
#include "Vthesis_p2_check_scw_frame_check.h"
#include "Vthesis_p2_disparity.h"
#include "Vthesis_p2_disparity_scw_disparity.h"
#include "Vthesis_p2_grid.h"
#include "Vthesis_p2_grid_scw_rectify_map_grid.h"
#include "Vthesis_p2_rectify.h"
#include "Vthesis_p2_rectify_scw_rectify.h"
#include "Vthesis_p2_split.h"
#include "Vthesis_p2_split_scw_beat_split.h"
#endif
#include "Vthesis_warning.h"
#include "Vthesis_warning_scw_warning.h"
#include "hls/pipeline/pipeline_params.hpp"
#include "sim/pipeline_chain.hpp"

namespace scw::sim::thesis_build {

template <int P>
using Build = hls::pipeline::ThesisPipeline<P>;

template <int P>
using Check = typename FrameCheckModel<P, Build<P>::kMaxWidthPx, Build<P>::kMaxHeight>::params;

// Every Verilated model against the build it stands for.
static_assert(frame_check_params_match<Vthesis_p1_check_scw_frame_check, Check<1>>());
static_assert(map_grid_params_match<Vthesis_p1_grid_scw_rectify_map_grid, Build<1>::map_grid>());
static_assert(rectify_params_match<Vthesis_p1_rectify_scw_rectify, Build<1>::rectify>());
static_assert(disparity_params_match<Vthesis_p1_disparity_scw_disparity,
                                     hls::disparity::Disparity<Build<1>::disparity>>());
static_assert(labelling_params_match<Vthesis_labelling_scw_labelling, Build<1>::labelling>());
static_assert(warning_params_match<Vthesis_warning_scw_warning, Build<1>::warning>());
static_assert(result_merge_params_match<Vthesis_merge_scw_result_merge>());
static_assert(ground_params_match<Vthesis_ground_scw_ground, Build<1>::ground>());

#if SCW_THESIS_RTL_P2
static_assert(frame_check_params_match<Vthesis_p2_check_scw_frame_check, Check<2>>());
static_assert(map_grid_params_match<Vthesis_p2_grid_scw_rectify_map_grid, Build<2>::map_grid>());
static_assert(rectify_params_match<Vthesis_p2_rectify_scw_rectify, Build<2>::rectify>());
static_assert(disparity_params_match<Vthesis_p2_disparity_scw_disparity,
                                     hls::disparity::Disparity<Build<2>::disparity>>());
static_assert(beat_split_params_match<Vthesis_p2_split_scw_beat_split, std::uint16_t, 2>());
#endif

template <int P>
struct Rtl;
template <>
struct Rtl<1> {
  using type = PipelineRtl<Vthesis_p1_check, Vthesis_p1_grid, Vthesis_p1_rectify,
                           Vthesis_p1_disparity, void, Vthesis_labelling, Vthesis_warning,
                           Vthesis_merge, Vthesis_ground>;
};
#if SCW_THESIS_RTL_P2
template <>
struct Rtl<2> {
  using type = PipelineRtl<Vthesis_p2_check, Vthesis_p2_grid, Vthesis_p2_rectify,
                           Vthesis_p2_disparity, Vthesis_p2_split, Vthesis_labelling,
                           Vthesis_warning, Vthesis_merge, Vthesis_ground>;
};
#endif

}  // namespace scw::sim::thesis_build
