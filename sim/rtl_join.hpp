// SPDX-License-Identifier: Apache-2.0
// A Verilated two-input stage as a join model, interchangeable with its C++ twin.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <utility>

#include "sim/join.hpp"
#include "sim/pack.hpp"
#include "sim/rtl_stream.hpp"
#include "sim/verilated_harness.hpp"

namespace scw::sim {

/// Names the two input port groups of a join module: SCW_JOIN_PORTS(RectifyPorts, in, map)
/// binds in_valid_i/in_ready_o/in_data_i/in_sof_i/in_eol_i and map_valid_i/... .
#define SCW_JOIN_PORTS(NAME, A, B)                                                           \
  struct NAME {                                                                              \
    template <typename VM>                                                                   \
    static void drive_a(VM& m, bool v, const ::scw::sim::Bits& p, bool sof, bool eol) {      \
      m.A##_valid_i = v;                                                                     \
      p.to_port(m.A##_data_i);                                                               \
      m.A##_sof_i = sof;                                                                     \
      m.A##_eol_i = eol;                                                                     \
    }                                                                                        \
    template <typename VM>                                                                   \
    static void drive_b(VM& m, bool v, const ::scw::sim::Bits& p, bool sof, bool eol) {      \
      m.B##_valid_i = v;                                                                     \
      p.to_port(m.B##_data_i);                                                               \
      m.B##_sof_i = sof;                                                                     \
      m.B##_eol_i = eol;                                                                     \
    }                                                                                        \
    template <typename VM>                                                                   \
    static bool a_ready(const VM& m) {                                                       \
      return m.A##_ready_o;                                                                  \
    }                                                                                        \
    template <typename VM>                                                                   \
    static bool b_ready(const VM& m) {                                                       \
      return m.B##_ready_o;                                                                  \
    }                                                                                        \
  }

/// Binds a module with two input groups (named by `Ports`) and out_valid_o/out_ready_i/
/// out_data_o/out_sof_o/out_eol_o. `configure` sets the module's static cfg_* inputs once,
/// before reset; Verilator keeps input values, so they stay stable throughout.
template <typename VM, typename A, typename B, typename Out, typename Ports>
class RtlJoin {
 public:
  using a_type = A;
  using b_type = B;
  using out_type = Out;

  RtlJoin(const std::string& name, std::function<void(VM&)> configure)
      : h_(std::make_unique<Harness<VM>>(name)) {
    configure(h_->dut());
    h_->reset();
  }

  JoinOutputs<Out> eval(bool a_valid, const A& a, bool b_valid, const B& b, bool out_ready) {
    VM& m = h_->dut();
    Ports::drive_a(m, a_valid, BeatLayout<A>::payload(a), BeatLayout<A>::sof(a),
                   BeatLayout<A>::eol(a));
    Ports::drive_b(m, b_valid, BeatLayout<B>::payload(b), BeatLayout<B>::sof(b),
                   BeatLayout<B>::eol(b));
    m.out_ready_i = out_ready;
    m.eval();
    JoinOutputs<Out> o;
    o.a_ready = Ports::a_ready(m);
    o.b_ready = Ports::b_ready(m);
    o.out_valid = m.out_valid_o;
    o.out = read_stage_out<Out>(m);
    return o;
  }
  void tick() { h_->tick(); }

  Harness<VM>& harness() { return *h_; }
  VM& dut() { return h_->dut(); }

 private:
  std::unique_ptr<Harness<VM>> h_;
};

}  // namespace scw::sim
