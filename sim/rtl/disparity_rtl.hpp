// SPDX-License-Identifier: Apache-2.0
// The Verilated scw_disparity as a join model: left pixels on l_*, right pixels on r_*.
#pragma once

#include <algorithm>
#include <string>

#include "hls/disparity/disparity.hpp"
#include "sim/rtl/rtl_join.hpp"
#include "sim/words/disparity_cfg.hpp"

namespace scw::sim {

SCW_JOIN_PORTS(DisparityPorts, l, r);

/// `VM` is a Verilated scw_disparity built with `Params` (check with disparity_params_match).
template <typename VM, typename Params>
using DisparityRtl = RtlJoin<VM, typename Params::pixel_beat, typename Params::pixel_beat,
                             typename Params::disp_beat, DisparityPorts>;

/// Drives the frame's size and the configuration word cfg_disparity_i from `cfg` (scw_disparity,
/// or a top that passes them on), the word packed by its one field table from what the build
/// reads (disparity_cfg::port_config).
template <typename VM, typename Params>
void drive_disparity_cfg(VM& m, const hls::disparity::DisparityConfig& cfg) {
  m.cfg_width_i = static_cast<unsigned>(std::max(cfg.width, 0));
  m.cfg_height_i = static_cast<unsigned>(std::max(cfg.height, 0));
  words::pack_word(disparity_cfg::port_config<Params::kNumDisp>(cfg), disparity_cfg::kConfigFields)
      .to_port(m.cfg_disparity_i);
}

template <typename VM, typename Params>
DisparityRtl<VM, Params> make_disparity_rtl(const std::string& name,
                                            const hls::disparity::DisparityConfig& cfg) {
  return DisparityRtl<VM, Params>(name, [cfg](VM& m) { drive_disparity_cfg<VM, Params>(m, cfg); });
}

}  // namespace scw::sim
