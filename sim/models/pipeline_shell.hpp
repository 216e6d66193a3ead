// SPDX-License-Identifier: Apache-2.0
// Clocks an HLS kernel's per-beat step() as an RTL pipeline of a declared depth would run, and
// the slot register that every clocked model of a pipeline under one enable is built on.
#pragma once

#include <array>
#include <optional>

#include "sim/core/cycle_model.hpp"

namespace scw::sim {

/// The data registers of a `Latency`-stage pipeline under one enable, the shape of the RTL stage
/// cores: the whole pipeline moves when its last slot is empty or being read, so a beat that
/// enters at an enabled edge is presented `Latency` enabled edges later. The models compute a
/// beat when it enters (their state changes at that edge, as the RTL's does); the slots only
/// delay the result.
template <typename T, int Latency>
class SlotRegister {
  static_assert(Latency >= 1, "a pipeline has at least its output register");

 public:
  bool out_valid() const { return slots_[last()].has_value(); }
  const T& out() const { return *slots_[last()]; }
  /// The first slot, for models whose input side looks into the pipeline (rectify's writer).
  const std::optional<T>& first() const { return slots_[first_]; }

  /// The pipeline's enable: its last slot is empty or read this cycle.
  bool enable(bool out_ready) const { return !out_valid() || out_ready; }
  /// Presents the last slot on `o` (StreamOutputs, JoinOutputs, SideOutputs...).
  template <typename Outputs>
  void present(Outputs& o) const {
    o.out_valid = out_valid();
    if (o.out_valid) o.out = out();
  }
  /// An enabled edge: every slot moves on and the first takes `make()` if `valid`, else a
  /// bubble. `make` is called only for a beat that enters, since it is the kernel's step.
  template <typename Make>
  void advance(bool valid, Make&& make) {
    // A ring: the slots move on by moving where the first one is; the last slot's place, whose
    // beat leaves, becomes the new first.
    first_ = last();
    slots_[first_].reset();
    if (valid) slots_[first_] = make();
  }

 private:
  int last() const { return first_ == 0 ? Latency - 1 : first_ - 1; }

  std::array<std::optional<T>, Latency> slots_{};
  int first_ = 0;  // slot i is slots_[(first_ + i) % Latency]
};

/// A kernel's step() behind a SlotRegister of `Latency` stages: in_ready = !out_valid ||
/// out_ready and a beat accepted in cycle t is presented from t + Latency on.
template <typename Kernel, int Latency>
class PipelineShell {
 public:
  using in_type = typename Kernel::in_type;
  using out_type = typename Kernel::out_type;

  StreamOutputs<out_type> eval(bool in_valid, const in_type& in, bool out_ready) {
    StreamOutputs<out_type> o;
    slots_.present(o);
    advance_ = slots_.enable(out_ready);
    o.in_ready = advance_;
    in_valid_ = in_valid;
    in_ = in;
    return o;
  }
  void tick() {
    if (advance_) slots_.advance(in_valid_, [this] { return kernel_.step(in_); });
  }

  Kernel& kernel() { return kernel_; }
  const Kernel& kernel() const { return kernel_; }

 private:
  Kernel kernel_{};
  SlotRegister<out_type, Latency> slots_;
  bool advance_ = false;
  bool in_valid_ = false;
  in_type in_{};
};

}  // namespace scw::sim
