// SPDX-License-Identifier: Apache-2.0
// The Verilated scw_labelling as a stream model (disparities in, object words out), and the
// compile-time check that it was built with the C++ parameters.
#pragma once

#include <string>

#include "hls/labelling/labelling.hpp"
#include "sim/rtl/rtl_stream.hpp"
#include "sim/words/labelling_cfg.hpp"
#include "sim/words/labelling_pack.hpp"

namespace scw::sim {

/// The RTL's descriptor field widths (public localparams) are hls::labelling::desc_widths'.
template <typename VM>
constexpr bool labelling_widths_match(const hls::labelling::DescWidths& w) {
  return VM::AreaW == w.area && VM::PosXW == w.x && VM::PosYW == w.y && VM::DispW == w.d &&
         VM::M10W == w.m[0] && VM::M01W == w.m[1] && VM::M20W == w.m[2] && VM::M11W == w.m[3] &&
         VM::M02W == w.m[4] && VM::M30W == w.m[5] && VM::M21W == w.m[6] && VM::M12W == w.m[7] &&
         VM::M03W == w.m[8] && VM::SumDW == w.sum_d && VM::SumDDW == w.sum_dd &&
         VM::DescW == w.total();
}

/// `VM` is a Verilated scw_labelling module class (its /*verilator public*/ parameters are
/// static constexpr members); `Params` an hls::labelling::LabellingParams. The edge queue's
/// depth, the lanes' FIFOs and the Init phase's length set when the stage takes input, so they
/// must be the model's too.
template <typename VM, typename Params>
constexpr bool labelling_params_match() {
  return VM::MaxWidthPx == Params::kMaxWidthPx && VM::MaxHeight == Params::kMaxHeight &&
         VM::MaxTilesX == Params::kMaxTilesX && VM::MaxTilesY == Params::kMaxTilesY &&
         VM::LabelsPerTile == Params::kLabelsPerTile && VM::MaxObjects == Params::kMaxObjects &&
         VM::Lanes == Params::kLanes && VM::LaneFifo == Params::kLaneFifo &&
         VM::Nodes == Params::kNodes && VM::EdgeQueue == hls::labelling::kEdgeQueue &&
         VM::TakeRoom == hls::labelling::kTakeRoom &&
         VM::InitClocks == hls::labelling::Labelling<Params>::kInitClocks &&
         labelling_widths_match<VM>(Params::kWidths);
}

/// `VM` is a Verilated scw_labelling built with `Params` (check with labelling_params_match).
template <typename VM, typename Params>
using LabellingRtl = RtlStream<VM, typename Params::in_beat, hls::labelling::LabelPacket>;

/// Sets the frame's size and the configuration word cfg_labelling_i (scw_labelling, or a top that
/// passes them on), the word packed by its one field table (labelling_cfg::port_config).
template <typename VM>
void drive_labelling_cfg(VM& m, const hls::labelling::LabellingConfig& cfg) {
  m.cfg_width_i = static_cast<unsigned>(cfg.width);
  m.cfg_height_i = static_cast<unsigned>(cfg.height);
  words::pack_word(labelling_cfg::port_config(cfg), labelling_cfg::kConfigFields)
      .to_port(m.cfg_labelling_i);
}

/// Checks `cfg` as the model does (std::invalid_argument) and drives the configuration from it
/// before reset.
template <typename VM, typename Params>
LabellingRtl<VM, Params> make_labelling_rtl(const std::string& name,
                                            const hls::labelling::LabellingConfig& cfg) {
  hls::labelling::check_config<Params>(cfg);
  return LabellingRtl<VM, Params>(name, [cfg](VM& m) { drive_labelling_cfg(m, cfg); });
}

}  // namespace scw::sim
