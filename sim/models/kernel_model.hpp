// SPDX-License-Identifier: Apache-2.0
// An hls/ kernel with an output register clocked as a one-in one-out stream model.
#pragma once

#include <utility>

#include "sim/core/cycle_model.hpp"

namespace scw::sim {

/// `Kernel` (clock(in_valid, in, out_ready), out_valid(), out()) as a cycle model whose output
/// register is the stage's output. Kernels differ only in what their in_ready depends on (the
/// beat's sof for labelling, out_ready for warning), so `Ready(kernel, in, out_ready)` says it.
/// The kernel sees the raw in_valid: it takes a beat only when it is ready, and may look at a
/// beat it refuses (labelling flags a sof in mid-frame).
template <typename Kernel,
          bool (*Ready)(const Kernel&, const typename Kernel::in_type&, bool out_ready)>
class KernelModel {
 public:
  using kernel_type = Kernel;
  using in_type = typename Kernel::in_type;
  using out_type = typename Kernel::out_type;

  template <typename Config>
  explicit KernelModel(const Config& cfg) : k_(cfg) {}

  StreamOutputs<out_type> eval(bool in_valid, const in_type& in, bool out_ready) {
    StreamOutputs<out_type> o;
    o.in_ready = Ready(k_, in, out_ready);
    o.out_valid = k_.out_valid();
    if (o.out_valid) o.out = k_.out();
    in_valid_ = in_valid;
    in_ = in;
    out_ready_ = out_ready;
    return o;
  }
  void tick() { k_.clock(in_valid_, in_, out_ready_); }

  Kernel& kernel() { return k_; }
  const Kernel& kernel() const { return k_; }

 private:
  Kernel k_;
  bool in_valid_ = false, out_ready_ = false;
  in_type in_{};
};

}  // namespace scw::sim
