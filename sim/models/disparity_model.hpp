// SPDX-License-Identifier: Apache-2.0
// The disparity kernel clocked as a join model: (left pixels, right pixels) -> disparities.
#pragma once

#include "hls/disparity/disparity.hpp"
#include "sim/core/join.hpp"
#include "sim/models/pipeline_shell.hpp"

namespace scw::sim {

/// hls::disparity::Disparity behind an output register: the reader's beat is presented the
/// cycle after it is formed; the writer takes both inputs together.
template <typename Params>
class DisparityModel {
 public:
  using Kernel = hls::disparity::Disparity<Params>;
  using a_type = typename Kernel::in_type;
  using b_type = typename Kernel::in_type;
  using out_type = typename Kernel::out_type;
  static constexpr int kLatency = 1;

  explicit DisparityModel(const hls::disparity::DisparityConfig& cfg) : k_(cfg) {}

  JoinOutputs<out_type> eval(bool a_valid, const a_type& a, bool b_valid, const b_type& b,
                             bool out_ready) {
    JoinOutputs<out_type> o;
    slots_.present(o);
    advance_ = slots_.enable(out_ready);
    take_ = k_.in_ready(a_valid, b_valid);
    o.a_ready = take_;
    o.b_ready = take_;
    a_ = a;
    b_ = b;
    return o;
  }
  void tick() {
    const auto e = k_.clock(take_, a_, b_, advance_);
    if (advance_) slots_.advance(e.valid, [&e] { return e.beat; });
  }

  Kernel& kernel() { return k_; }

 private:
  Kernel k_;
  SlotRegister<out_type, kLatency> slots_;
  bool advance_ = false, take_ = false;
  a_type a_{};
  b_type b_{};
};

}  // namespace scw::sim
