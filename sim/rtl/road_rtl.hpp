// SPDX-License-Identifier: Apache-2.0
// The Verilated scw_road as a stream model (disparities in and out) or with its line output, and
// the compile-time check that it was built with the C++ parameters.
#pragma once

#include <cstdint>
#include <string>

#include "hls/road/road.hpp"
#include "sim/core/side_component.hpp"
#include "sim/rtl/rtl_stream.hpp"
#include "sim/words/road_cfg.hpp"

namespace scw::sim {

/// `VM` is a Verilated scw_road module class (its /*verilator public*/ parameters are static
/// constexpr members); `Params` an hls::road::RoadParams. The pipeline depth, the fit's length
/// and the fraction bits set the stage's timing and arithmetic.
template <typename VM, typename Params>
constexpr bool road_params_match() {
  return VM::Ppc == Params::kPpc && VM::MaxWidthPx == Params::kMaxWidthPx &&
         VM::MaxHeight == Params::kMaxHeight && VM::Latency == hls::road::kLatency &&
         VM::FitClocks == hls::road::kFitClocks && VM::FracBits == hls::road::kFracBits;
}

/// `VM` is a Verilated scw_road built with `Params` (check with road_params_match), as a
/// one-output stream model: its line output is always read (make_road_rtl ties line_ready_i
/// high), as RoadModel's three-argument eval has it.
template <typename VM, typename Params>
using RoadRtl = RtlStream<VM, typename Params::in_beat, typename Params::out_beat>;

/// Drives the configuration word cfg_road_i of a scw_road (or of a top that passes it through)
/// from `cfg`, packed by its one field table.
template <typename VM>
void drive_road_cfg(VM& m, const hls::road::RoadConfig& cfg) {
  words::pack_word(cfg, road_cfg::kConfigFields).to_port(m.cfg_road_i);
}

/// Checks `cfg` as the model does (std::invalid_argument) and drives the cfg_* ports from it
/// before reset.
template <typename VM, typename Params>
RoadRtl<VM, Params> make_road_rtl(const std::string& name, const hls::road::RoadConfig& cfg) {
  hls::road::check_config(cfg);
  return RoadRtl<VM, Params>(name, [cfg](VM& m) {
    drive_road_cfg(m, cfg);
    m.line_ready_i = 1;
  });
}

/// A Verilated scw_road with its line output, RoadModel's four-argument shape (SideComponent).
template <typename VM, typename Params>
class RoadSideRtl : public RtlAdapter<VM> {
 public:
  using in_type = typename Params::in_beat;
  using out_type = typename Params::out_beat;
  using side_type = hls::road::Line;

  /// Checks `cfg` as the model does (std::invalid_argument) and drives cfg_* before reset.
  RoadSideRtl(const std::string& name, const hls::road::RoadConfig& cfg)
      : RtlAdapter<VM>(name, [&cfg](VM& m) {
          hls::road::check_config(cfg);
          drive_road_cfg(m, cfg);
        }) {}

  SideOutputs<out_type, side_type> eval(bool in_valid, const in_type& in, bool out_ready,
                                        bool line_ready) {
    VM& m = this->dut();
    drive_stage_in(m, in_valid, in, out_ready);
    m.line_ready_i = line_ready;
    auto o = settle_out<SideOutputs<out_type, side_type>>(this->harness());
    o.in_ready = m.in_ready_o != 0;
    o.flag_valid = m.line_valid_o != 0;
    if (o.flag_valid) {
      o.flag.a = static_cast<std::int32_t>(m.line_a_o);
      o.flag.b = static_cast<std::int32_t>(static_cast<std::uint32_t>(m.line_b_o));
    }
    return o;
  }
};

}  // namespace scw::sim
