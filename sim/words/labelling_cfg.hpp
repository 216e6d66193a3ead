// SPDX-License-Identifier: Apache-2.0
// The labelling stage's configuration as one word, what the RTL's cfg_labelling_i port takes (of
// scw_labelling and of the scw_pipeline top) and the vector sets store: its fields are listed
// once, in kConfigFields, with the widths of rtl_models/common/scw_pkg.sv (scw_pkg.hpp is
// generated from it), where the RTL's word is labelling_cfg_t. The frame's width and height are
// not in it: the top's cfg_width_i and cfg_height_i, which every stage reads.
#pragma once

#include <algorithm>
#include <tuple>

#include "hls/labelling/labelling_params.hpp"
#include "scw_pkg.hpp"
#include "sim/words/fields.hpp"

namespace scw::sim::labelling_cfg {

using hls::labelling::LabellingConfig;
using words::Field;

/// Least significant first: labelling_cfg_t read from its last member up. The floor is Q11.4
/// two's complement (an invalid code of -16 is a floor of 0xfff0).
inline constexpr auto kConfigFields = std::make_tuple(
    Field<LabellingConfig, int, false>{"tile_w", pkg::LabTileBits, &LabellingConfig::tile_w},
    Field<LabellingConfig, int, false>{"tile_h", pkg::LabTileBits, &LabellingConfig::tile_h},
    Field<LabellingConfig, int>{"floor", pkg::LabFloorBits, &LabellingConfig::floor},
    Field<LabellingConfig, int, false>{"min_area", pkg::LabMinAreaBits,
                                       &LabellingConfig::min_area});

inline constexpr int kBits = words::bits_of(kConfigFields);
static_assert(words::fits_types(kConfigFields), "each field fits its C++ member");

/// What the stage's word carries for `cfg`: a tile wider or taller than 65535 never closes inside
/// a frame, nor does one of 65535 (its last column or row is the image's), so the 16-bit tile
/// sizes saturate.
inline LabellingConfig port_config(const LabellingConfig& cfg) {
  constexpr int kTileMax = (1 << pkg::LabTileBits) - 1;
  LabellingConfig p = cfg;
  p.tile_w = std::clamp(cfg.tile_w, 0, kTileMax);
  p.tile_h = std::clamp(cfg.tile_h, 0, kTileMax);
  return p;
}

}  // namespace scw::sim::labelling_cfg
