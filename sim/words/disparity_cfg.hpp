// SPDX-License-Identifier: Apache-2.0
// The disparity stage's configuration as one word, what the RTL's cfg_disparity_i port takes (of
// scw_disparity and of the scw_pipeline top) and the vector sets store: its fields are listed
// once, in kConfigFields, with the widths of rtl_models/common/scw_pkg.sv (scw_pkg.hpp is
// generated from it), where the RTL's word is disparity_cfg_t. The frame's width and height are
// not in it: the top's cfg_width_i and cfg_height_i, which every stage reads.
#pragma once

#include <algorithm>
#include <tuple>

#include "hls/disparity/disparity.hpp"
#include "scw_pkg.hpp"
#include "sim/words/fields.hpp"

namespace scw::sim::disparity_cfg {

using hls::disparity::DisparityConfig;
using words::Field;

/// Least significant first: disparity_cfg_t read from its last member up. Every field is a code
/// the stage reads as unsigned: port_config() makes the values so.
inline constexpr auto kConfigFields = std::make_tuple(
    Field<DisparityConfig, int, false>{"dmin", pkg::DispDminBits, &DisparityConfig::dmin},
    Field<DisparityConfig, int, false>{"num_disp", pkg::DispNumBits, &DisparityConfig::num_disp},
    Field<DisparityConfig, bool>{"prefilter", 1, &DisparityConfig::prefilter},
    Field<DisparityConfig, int, false>{"prefilter_cap", pkg::DispCapBits,
                                       &DisparityConfig::prefilter_cap},
    Field<DisparityConfig, int, false>{"sad_limit", pkg::DispLimitBits,
                                       &DisparityConfig::sad_limit},
    Field<DisparityConfig, int, false>{"texture_threshold", pkg::DispLimitBits,
                                       &DisparityConfig::texture_threshold},
    Field<DisparityConfig, int, false>{"uniqueness_ratio", pkg::DispRatioBits,
                                       &DisparityConfig::uniqueness_ratio},
    Field<DisparityConfig, bool>{"subpixel", 1, &DisparityConfig::subpixel},
    Field<DisparityConfig, bool>{"opencv_invalid", 1, &DisparityConfig::opencv_invalid},
    Field<DisparityConfig, int, false>{"edge_candidates", pkg::DispNumBits,
                                       &DisparityConfig::edge_candidates});

inline constexpr int kBits = words::bits_of(kConfigFields);
static_assert(words::fits_types(kConfigFields), "each field fits its C++ member");

/// What the stage's word carries for `cfg` at a build of NumDisp candidates: the candidate count
/// and the edge band as the model reads them (candidates, edge_min), and the SAD limit and
/// texture threshold saturated at 0 (a negative value means off, as 0 does; no SAD reaches 2^31).
template <int NumDisp>
DisparityConfig port_config(const DisparityConfig& cfg) {
  DisparityConfig p = cfg;
  p.num_disp = hls::disparity::candidates<NumDisp>(cfg);
  p.edge_candidates = hls::disparity::edge_min<NumDisp>(cfg);
  p.dmin = std::max(cfg.dmin, 0);
  p.prefilter_cap = std::max(cfg.prefilter_cap, 0);
  p.sad_limit = std::max(cfg.sad_limit, 0);
  p.texture_threshold = std::max(cfg.texture_threshold, 0);
  p.uniqueness_ratio = std::max(cfg.uniqueness_ratio, 0);
  return p;
}

}  // namespace scw::sim::disparity_cfg
