// SPDX-License-Identifier: Apache-2.0
// The warning stage's configuration as one word, what the RTL's cfg_warning_i port takes (of
// scw_warning and of the scw_pipeline top) and the vector sets store: its fields are listed once,
// in kConfigFields, with the widths of rtl_models/common/scw_pkg.sv (scw_pkg.hpp is generated
// from it), where the RTL's word is warning_cfg_t. The drive of the Verilated port, the sets'
// cfg hex and its layout JSON walk the same table; the total is scw_pkg::WarningCfgBits,
// static_asserted against kBits where a model is built (sim/builds/).
#pragma once

#include <cstdint>
#include <tuple>

#include "hls/warning/warning_params.hpp"
#include "scw_pkg.hpp"
#include "sim/words/fields.hpp"

namespace scw::sim::warning_cfg {

using hls::warning::DistanceRule;
using hls::warning::WarningConfig;
using words::Field;

/// Least significant first: warning_cfg_t read from its last member up. road_height is not in
/// the word: it is a port of its own (cfg_road_height_i), tied high in the top.
inline constexpr int kField = pkg::CfgFieldBits;
inline constexpr auto kConfigFields = std::make_tuple(
    Field<WarningConfig, std::uint32_t>{"baseline_q8", pkg::CfgBaselineBits,
                                        &WarningConfig::baseline_q8},
    Field<WarningConfig, std::uint16_t>{"focal_q4", kField, &WarningConfig::focal_q4},
    Field<WarningConfig, std::uint16_t>{"cu_q4", kField, &WarningConfig::cu_q4},
    Field<WarningConfig, std::uint16_t>{"cv_q4", kField, &WarningConfig::cv_q4},
    Field<WarningConfig, std::int16_t>{"veh_x_mm", kField, &WarningConfig::veh_x_mm},
    Field<WarningConfig, std::int16_t>{"veh_y_mm", kField, &WarningConfig::veh_y_mm},
    Field<WarningConfig, std::int16_t>{"veh_z_mm", kField, &WarningConfig::veh_z_mm},
    Field<WarningConfig, std::uint16_t>{"tunnel_half_w_mm", kField,
                                        &WarningConfig::tunnel_half_w_mm},
    Field<WarningConfig, std::uint16_t>{"tunnel_h_mm", kField, &WarningConfig::tunnel_h_mm},
    Field<WarningConfig, std::uint16_t>{"high_mm", kField, &WarningConfig::high_mm},
    Field<WarningConfig, std::uint16_t>{"medium_mm", kField, &WarningConfig::medium_mm},
    Field<WarningConfig, std::uint16_t>{"near_mm", kField, &WarningConfig::near_mm},
    Field<WarningConfig, std::uint16_t>{"min_height_mm", kField, &WarningConfig::min_height_mm},
    Field<WarningConfig, std::uint16_t>{"d_limit_q4", kField, &WarningConfig::d_limit_q4},
    Field<WarningConfig, DistanceRule>{"rule", 1, &WarningConfig::rule},
    Field<WarningConfig, std::uint8_t>{"spread_q4", pkg::CfgSpreadBits, &WarningConfig::spread_q4});

inline constexpr int kBits = words::bits_of(kConfigFields);
static_assert(words::fits_types(kConfigFields), "each field fits its C++ member");

}  // namespace scw::sim::warning_cfg
