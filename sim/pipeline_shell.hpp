// SPDX-License-Identifier: Apache-2.0
// Clocks an HLS kernel's per-beat step() as an RTL pipeline of a declared depth would run.
#pragma once

#include <array>
#include <optional>

#include "sim/cycle_model.hpp"

namespace scw::sim {

/// A `Latency`-stage pipeline under one enable, the shape of the RTL stage cores:
/// the whole pipeline advances when its last stage is empty or being read, so
/// in_ready = !out_valid || out_ready and a beat accepted in cycle t is presented from
/// t + Latency on. The kernel computes the beat when it enters (its state changes at the
/// accepting edge, as the RTL's does); the slots only delay the result.
template <typename Kernel, int Latency>
class PipelineShell {
  static_assert(Latency >= 1, "a pipeline has at least its output register");

 public:
  using in_type = typename Kernel::in_type;
  using out_type = typename Kernel::out_type;

  StreamOutputs<out_type> eval(bool in_valid, const in_type& in, bool out_ready) {
    StreamOutputs<out_type> o;
    o.out_valid = slots_[Latency - 1].has_value();
    if (o.out_valid) o.out = *slots_[Latency - 1];
    advance_ = !o.out_valid || out_ready;
    o.in_ready = advance_;
    in_valid_ = in_valid;
    in_ = in;
    return o;
  }
  void tick() {
    if (!advance_) return;
    for (int i = Latency - 1; i > 0; --i) slots_[i] = slots_[i - 1];
    slots_[0].reset();
    if (in_valid_) slots_[0] = kernel_.step(in_);
  }

  Kernel& kernel() { return kernel_; }
  const Kernel& kernel() const { return kernel_; }

 private:
  Kernel kernel_{};
  std::array<std::optional<out_type>, Latency> slots_{};
  bool advance_ = false;
  bool in_valid_ = false;
  in_type in_{};
};

}  // namespace scw::sim
