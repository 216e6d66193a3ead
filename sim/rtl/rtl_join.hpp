// SPDX-License-Identifier: Apache-2.0
// A Verilated two-input stage as a join model, interchangeable with its C++ twin.
#pragma once

#include <functional>
#include <string>

#include "sim/core/join.hpp"
#include "sim/rtl/rtl_adapter.hpp"

namespace scw::sim {

/// Names the two input port groups of a join module: SCW_JOIN_PORTS(RectifyPorts, in, map)
/// binds in_valid_i/in_ready_o/in_data_i/in_sof_i/in_eol_i as `a` and map_valid_i/... as `b`.
/// A module whose second input is not a standard group writes its own `b` beside
/// SCW_IN_PORTS(a, ...) (warning_rtl.hpp).
#define SCW_JOIN_PORTS(NAME, A, B) \
  struct NAME {                    \
    SCW_IN_PORTS(a, A);            \
    SCW_IN_PORTS(b, B);            \
  }

/// Binds a module with two input groups (named by `Ports`) and out_valid_o/out_ready_i/
/// out_data_o with the beat's flags (out_sof_o/out_eol_o or out_last_o).
template <typename VM, typename A, typename B, typename Out, typename Ports>
class RtlJoin : public RtlAdapter<VM> {
 public:
  using a_type = A;
  using b_type = B;
  using out_type = Out;

  /// `configure` sets the module's static cfg_* inputs once, before reset.
  RtlJoin(const std::string& name, const std::function<void(VM&)>& configure)
      : RtlAdapter<VM>(name, configure) {}

  JoinOutputs<Out> eval(bool a_valid, const A& a, bool b_valid, const B& b, bool out_ready) {
    VM& m = this->dut();
    Ports::a::drive(m, a_valid, a);
    Ports::b::drive(m, b_valid, b);
    m.out_ready_i = out_ready;
    auto o = settle_out<JoinOutputs<Out>>(
        this->harness(), QuietKey::bits(a_valid, b_valid, out_ready), [&](const VM& d) {
          const bool ar = Ports::a::ready(d), br = Ports::b::ready(d);
          const bool moved = (a_valid && ar) || (b_valid && br) || (d.out_valid_o && out_ready);
          return moved ? QuietKey::kBusy : QuietKey::bits(ar, br, d.out_valid_o);
        });
    o.a_ready = Ports::a::ready(m);
    o.b_ready = Ports::b::ready(m);
    return o;
  }
};

}  // namespace scw::sim
