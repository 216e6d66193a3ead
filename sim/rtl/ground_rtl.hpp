// SPDX-License-Identifier: Apache-2.0
// The Verilated scw_ground as a stream model (disparities in and out), and the compile-time
// check that it was built with the C++ parameters.
#pragma once

#include <string>

#include "hls/ground/ground.hpp"
#include "sim/rtl/rtl_stream.hpp"

namespace scw::sim {

/// `VM` is a Verilated scw_ground module class (its /*verilator public*/ parameters are static
/// constexpr members); `Params` an hls::ground::GroundParams. The window height and both
/// pipelines' depths must be the model's too: they set the stage's timing.
template <typename VM, typename Params>
constexpr bool ground_params_match() {
  return VM::MaxWidthPx == Params::kMaxWidthPx && VM::Rows == Params::kRows &&
         VM::LineLatency == Params::kLineLatency &&
         VM::DecideLatency == hls::ground::kDecideLatency && VM::Latency == Params::kLatency;
}

/// `VM` is a Verilated scw_ground built with `Params` (check with ground_params_match).
template <typename VM, typename Params>
using GroundRtl = RtlStream<VM, typename Params::in_beat, typename Params::out_beat>;

/// Checks `cfg` as the model does (std::invalid_argument) and drives the cfg_* ports from it
/// before reset.
template <typename VM, typename Params>
GroundRtl<VM, Params> make_ground_rtl(const std::string& name,
                                      const hls::ground::GroundConfig& cfg) {
  hls::ground::check_config(cfg);
  return GroundRtl<VM, Params>(name, [cfg](VM& m) {
    m.cfg_enable_i = cfg.enable ? 1 : 0;
    m.cfg_step_tol_i = static_cast<unsigned>(cfg.step_tol_q4);
    m.cfg_min_rise_i = static_cast<unsigned>(cfg.min_rise_q4);
    m.cfg_max_rise_i = static_cast<unsigned>(cfg.max_rise_q4);
  });
}

}  // namespace scw::sim
