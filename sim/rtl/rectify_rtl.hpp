// SPDX-License-Identifier: Apache-2.0
// The Verilated scw_rectify as a join model: raw pixels on in_*, the map on map_*.
#pragma once

#include <string>

#include "hls/rectify/rectify_params.hpp"
#include "sim/rtl/rtl_join.hpp"

namespace scw::sim {

SCW_JOIN_PORTS(RectifyPorts, in, map);

/// `VM` is a Verilated scw_rectify built with `Params` (check with rectify_params_match).
template <typename VM, typename Params>
using RectifyRtl = RtlJoin<VM, typename Params::pixel_beat, typename Params::map_beat,
                           typename Params::pixel_beat, RectifyPorts>;

template <typename VM, typename Params>
RectifyRtl<VM, Params> make_rectify_rtl(const std::string& name,
                                        const hls::rectify::RectifyConfig& cfg) {
  return RectifyRtl<VM, Params>(name, [cfg](VM& m) {
    m.cfg_width_i = static_cast<unsigned>(cfg.width);
    m.cfg_height_i = static_cast<unsigned>(cfg.height);
    m.cfg_lead_i = static_cast<unsigned>(cfg.lead_rows);
  });
}

}  // namespace scw::sim
