// SPDX-License-Identifier: Apache-2.0
// The Verilated scw_frame_check with the C++ model's interface, and its parameter check.
#pragma once

#include <string>

#include "hls/pipeline/frame_check.hpp"
#include "sim/models/frame_check_model.hpp"
#include "sim/rtl/rtl_adapter.hpp"

namespace scw::sim {

/// `VM` is a Verilated scw_frame_check module class (its /*verilator public*/ parameters are
/// static constexpr members); `Params` an hls::pipeline::FrameCheckParams. The latency is the
/// model's too: it sets the block's timing.
template <typename VM, typename Params>
constexpr bool frame_check_params_match() {
  return VM::Ppc == Params::kPpc && VM::MaxWidthPx == Params::kMaxWidthPx &&
         VM::MaxHeight == Params::kMaxHeight && VM::Latency == Params::kLatency;
}

/// A Verilated scw_frame_check built with `Params` (check with frame_check_params_match) as a
/// cycle model of FrameCheckModel's shape, so a test or a SideComponent drives either.
template <typename VM, typename Params>
class FrameCheckRtl : public RtlAdapter<VM> {
 public:
  using params = Params;
  using in_type = typename Params::beat_type;
  using out_type = in_type;
  using flag_type = hls::pipeline::FrameFlagPacket;
  using side_type = hls::pipeline::FrameFlag;

  /// Checks `cfg` as the model does (std::invalid_argument) and drives cfg_* before reset.
  FrameCheckRtl(const std::string& name, const hls::pipeline::FrameCheckConfig& cfg)
      : RtlAdapter<VM>(name, [&cfg](VM& m) {
          hls::pipeline::check_frame_check_config<Params>(cfg);
          m.cfg_width_i = static_cast<unsigned>(cfg.width);
          m.cfg_height_i = static_cast<unsigned>(cfg.height);
        }) {}

  FrameCheckOutputs<out_type> eval(bool in_valid, const in_type& in, bool out_ready,
                                   bool flag_ready) {
    VM& m = this->dut();
    drive_stage_in(m, in_valid, in, out_ready);
    m.flag_ready_i = flag_ready;
    auto o = settle_out<FrameCheckOutputs<out_type>>(this->harness());
    o.in_ready = m.in_ready_o != 0;
    o.flag_valid = m.flag_valid_o != 0;
    if (o.flag_valid) o.flag.error = m.flag_error_o != 0;
    return o;
  }
};

}  // namespace scw::sim
