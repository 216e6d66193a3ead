// SPDX-License-Identifier: Apache-2.0
// The warning kernel clocked as a one-in one-out stream model: object words -> frame results.
#pragma once

#include "hls/warning/warning.hpp"
#include "sim/cycle_model.hpp"
#include "sim/labelling_pack.hpp"
#include "sim/warning_pack.hpp"

namespace scw::sim {

/// hls::warning::Warning as a cycle model: its output register is the stage's output.
template <typename Params>
class WarningModel {
 public:
  using Kernel = hls::warning::Warning<Params>;
  using in_type = typename Kernel::in_type;
  using out_type = typename Kernel::out_type;

  explicit WarningModel(const hls::warning::WarningConfig& cfg) : k_(cfg) {}

  StreamOutputs<out_type> eval(bool in_valid, const in_type& in, bool out_ready) {
    StreamOutputs<out_type> o;
    o.in_ready = k_.in_ready(out_ready);
    o.out_valid = k_.out_valid();
    if (o.out_valid) o.out = k_.out();
    in_valid_ = in_valid && o.in_ready;
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
