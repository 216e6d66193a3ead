// SPDX-License-Identifier: Apache-2.0
// The Verilated scw_disparity as a join model: left pixels on l_*, right pixels on r_*.
#pragma once

#include <algorithm>
#include <string>

#include "hls/disparity/disparity.hpp"
#include "sim/rtl/rtl_join.hpp"

namespace scw::sim {

SCW_JOIN_PORTS(DisparityPorts, l, r);

/// `VM` is a Verilated scw_disparity built with `Params` (check with disparity_params_match).
template <typename VM, typename Params>
using DisparityRtl = RtlJoin<VM, typename Params::pixel_beat, typename Params::pixel_beat,
                             typename Params::disp_beat, DisparityPorts>;

/// Drives the cfg_* ports from `cfg` (scw_disparity, or a top that passes them on); the SAD
/// limit and texture threshold saturate at the 32-bit ports (no SAD reaches 2^31), a negative
/// value means off as in the model.
template <typename VM, typename Params>
void drive_disparity_cfg(VM& m, const hls::disparity::DisparityConfig& cfg) {
  const auto port = [](int v) { return static_cast<unsigned>(std::max(v, 0)); };
  m.cfg_width_i = port(cfg.width);
  m.cfg_height_i = port(cfg.height);
  m.cfg_dmin_i = port(cfg.dmin);
  m.cfg_num_disp_i = port(hls::disparity::candidates<Params::kNumDisp>(cfg));
  m.cfg_prefilter_i = cfg.prefilter;
  m.cfg_cap_i = port(cfg.prefilter_cap);
  m.cfg_sad_limit_i = port(cfg.sad_limit);
  m.cfg_texture_i = port(cfg.texture_threshold);
  m.cfg_uniqueness_i = port(cfg.uniqueness_ratio);
  m.cfg_subpixel_i = cfg.subpixel;
  m.cfg_opencv_invalid_i = cfg.opencv_invalid;
  m.cfg_edge_i = port(hls::disparity::edge_min<Params::kNumDisp>(cfg));
}

template <typename VM, typename Params>
DisparityRtl<VM, Params> make_disparity_rtl(const std::string& name,
                                            const hls::disparity::DisparityConfig& cfg) {
  return DisparityRtl<VM, Params>(name, [cfg](VM& m) { drive_disparity_cfg<VM, Params>(m, cfg); });
}

}  // namespace scw::sim
