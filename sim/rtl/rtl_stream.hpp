// SPDX-License-Identifier: Apache-2.0
// A Verilated one-in one-out stream module as a cycle model, interchangeable with its C++ twin.
#pragma once

#include <functional>
#include <string>

#include "sim/core/cycle_model.hpp"
#include "sim/rtl/rtl_adapter.hpp"

namespace scw::sim {

/// Binds the common port shape (in_valid_i/in_ready_o/in_data_i, out_valid_o/out_ready_i/
/// out_data_o). Stage modules carry the beat's flags on ports of their own (in_sof_i/in_eol_i
/// or in_last_i, and the mirror out_*) and the payload in *_data; opaque elastic blocks (FIFO,
/// stream register, skid buffer) carry the whole packed beat {flags, payload} in *_data.
template <typename VM, typename In, typename Out>
class RtlStream : public RtlAdapter<VM> {
 public:
  using in_type = In;
  using out_type = Out;

  explicit RtlStream(const std::string& name) : RtlAdapter<VM>(name) {}
  /// `configure` sets the module's static cfg_* inputs once, before reset.
  RtlStream(const std::string& name, const std::function<void(VM&)>& configure)
      : RtlAdapter<VM>(name, configure) {}

  StreamOutputs<Out> eval(bool in_valid, const In& in, bool out_ready) {
    VM& m = this->dut();
    drive_stage_in(m, in_valid, in, out_ready);
    auto o = settle_out<StreamOutputs<Out>>(
        this->harness(), QuietKey::bits(in_valid, out_ready), [&](const VM& d) {
          const bool moved = (in_valid && d.in_ready_o) || (d.out_valid_o && out_ready);
          return moved ? QuietKey::kBusy : QuietKey::bits(d.in_ready_o, d.out_valid_o);
        });
    o.in_ready = m.in_ready_o;
    return o;
  }
};

}  // namespace scw::sim
