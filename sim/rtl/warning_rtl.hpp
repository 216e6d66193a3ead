// SPDX-License-Identifier: Apache-2.0
// The Verilated scw_warning as a stream model (object words in, frame results out) or a join
// with its road input, and the compile-time check that it was built with the C++ parameters.
#pragma once

#include <cstdint>
#include <string>

#include "hls/warning/warning.hpp"
#include "sim/rtl/rtl_join.hpp"
#include "sim/rtl/rtl_stream.hpp"
#include "sim/words/labelling_pack.hpp"
#include "sim/words/warning_cfg.hpp"
#include "sim/words/warning_pack.hpp"

namespace scw::sim {

/// `VM` is a Verilated scw_warning module class (its /*verilator public*/ parameters are static
/// constexpr members); `Params` an hls::warning::WarningParams. The pipeline depth must be the
/// model's too, or the two would fold words on different clocks.
template <typename VM, typename Params>
constexpr bool warning_params_match() {
  return VM::MaxDisparityPx == Params::kMaxDisparityPx && VM::TableSize == Params::kTableSize &&
         VM::RuleLatency == hls::warning::kRuleLatency && VM::Latency == hls::warning::kLatency;
}

/// Sets the warning stage's configuration word, cfg_warning_i (of scw_warning, or a top that
/// passes it on), packed by its one field table.
template <typename VM>
void drive_warning_cfg(VM& m, const hls::warning::WarningConfig& cfg) {
  words::pack_word(cfg, warning_cfg::kConfigFields).to_port(m.cfg_warning_i);
}

/// The ports of scw_warning as a join: `a` the object words (in_*, with in_last_i), `b` the road
/// line (road_valid_i/road_ready_o and the line's two words, one a frame).
struct WarningPorts {
  SCW_IN_PORTS(a, in);
  struct b {
    template <typename VM>
    static void drive(VM& m, bool valid, const hls::Packet<hls::warning::RoadLine>& line) {
      m.road_valid_i = valid;
      m.road_a_i = static_cast<std::uint32_t>(line.data.a) & 0x3ffffu;
      m.road_b_i = static_cast<std::uint32_t>(line.data.b);
    }
    template <typename VM>
    static bool ready(const VM& m) {
      return m.road_ready_o;
    }
  };
};

/// A Verilated scw_warning as a one-input stream model (sim::WarningModel's shape): the road
/// port idle, as configure_warning_rtl leaves it.
template <typename VM>
using WarningRtl = RtlStream<VM, hls::labelling::LabelPacket, hls::warning::ResultPacket>;

/// A Verilated scw_warning with its road input, as a join model (sim::WarningRoadModel's).
template <typename VM>
using WarningRoadRtl = RtlJoin<VM, hls::labelling::LabelPacket,
                               hls::Packet<hls::warning::RoadLine>, hls::warning::ResultPacket,
                               WarningPorts>;

/// The static inputs of both shapes: the cfg_* ports, and the road port idle with a zero line
/// (the join drives it every cycle; the stream shape never does).
template <typename VM>
void configure_warning_rtl(VM& m, const hls::warning::WarningConfig& cfg) {
  drive_warning_cfg(m, cfg);
  m.cfg_road_height_i = cfg.road_height;
  WarningPorts::b::drive(m, false, {});
}

/// Checks `cfg` as the model does (std::invalid_argument) and drives the cfg_* ports from it
/// before reset. `VM` is a Verilated scw_warning built with `Params` (warning_params_match).
template <typename VM, typename Params>
WarningRtl<VM> make_warning_rtl(const std::string& name, const hls::warning::WarningConfig& cfg) {
  hls::warning::check_config<Params>(cfg);
  return WarningRtl<VM>(name, [cfg](VM& m) { configure_warning_rtl(m, cfg); });
}

/// The same for the join shape, with a road line a frame (cfg.road_height).
template <typename VM, typename Params>
WarningRoadRtl<VM> make_warning_road_rtl(const std::string& name,
                                         const hls::warning::WarningConfig& cfg) {
  hls::warning::check_config<Params>(cfg);
  return WarningRoadRtl<VM>(name, [cfg](VM& m) { configure_warning_rtl(m, cfg); });
}

}  // namespace scw::sim
