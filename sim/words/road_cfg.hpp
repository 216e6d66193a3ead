// SPDX-License-Identifier: Apache-2.0
// The road stage's configuration as one word, what the RTL's cfg_road_i port takes (of scw_road
// and of the scw_pipeline top) and the vector sets store: its fields are listed once, in
// kConfigFields, with the widths of rtl_models/common/scw_pkg.sv (scw_pkg.hpp is generated from
// it), where the RTL's word is road_cfg_t. The drive of the Verilated port, the sets' cfg hex and
// its layout JSON walk the same table; the total is scw_pkg::RoadCfgBits, static_asserted
// against kBits where a model is built (sim/builds/).
#pragma once

#include <cstdint>
#include <tuple>

#include "hls/road/road_params.hpp"
#include "scw_pkg.hpp"
#include "sim/words/fields.hpp"

namespace scw::sim::road_cfg {

using hls::road::Line;
using hls::road::RoadConfig;
using words::Field;
using words::SubField;

/// Least significant first: road_cfg_t read from its last member up. The slopes are never
/// negative (check_config), so they are plain 18-bit codes; the intercept is two's complement.
inline constexpr auto kConfigFields = std::make_tuple(
    Field<RoadConfig, bool>{"enable", 1, &RoadConfig::enable},
    SubField<RoadConfig, Line, std::int32_t, false>{"nominal_a", pkg::RoadSlopeBits,
                                                    &RoadConfig::nominal, &Line::a},
    SubField<RoadConfig, Line, std::int32_t>{"nominal_b", pkg::RoadInterceptBits,
                                             &RoadConfig::nominal, &Line::b},
    Field<RoadConfig, std::int32_t, false>{"a_min", pkg::RoadSlopeBits, &RoadConfig::a_min},
    Field<RoadConfig, std::int32_t, false>{"a_max", pkg::RoadSlopeBits, &RoadConfig::a_max},
    Field<RoadConfig, std::uint16_t>{"h_min", pkg::RoadRowBits, &RoadConfig::h_min},
    Field<RoadConfig, std::uint16_t>{"h_max", pkg::RoadRowBits, &RoadConfig::h_max},
    Field<RoadConfig, std::uint16_t>{"tol_q4", pkg::RoadTolBits, &RoadConfig::tol_q4},
    Field<RoadConfig, std::uint8_t>{"tol_rel_q8", pkg::RoadRelBits, &RoadConfig::tol_rel_q8},
    Field<RoadConfig, std::uint16_t>{"gate_q4", pkg::RoadTolBits, &RoadConfig::gate_q4},
    Field<RoadConfig, std::uint8_t>{"gate_rel_q8", pkg::RoadRelBits, &RoadConfig::gate_rel_q8},
    Field<RoadConfig, std::uint32_t>{"min_count", pkg::RoadCountBits, &RoadConfig::min_count});

inline constexpr int kBits = words::bits_of(kConfigFields);
static_assert(words::fits_types(kConfigFields), "each field fits its C++ member");
static_assert(pkg::RoadSlopeBits == hls::road::kSlopeBits, "the RTL's slope is the model's");

}  // namespace scw::sim::road_cfg
