// SPDX-License-Identifier: Apache-2.0
// The road kernel clocked as its RTL: a two-register pipeline under one enable, and the fit
// between frames that holds the next sof.
#pragma once

#include <array>
#include <optional>

#include "hls/road/road.hpp"
#include "sim/cycle_model.hpp"

namespace scw::sim {

/// hls::road::Road as a cycle model of scw_road, clock for clock:
///   - the pipeline (kLatency slots) advances when its last slot is empty or read; the kernel's
///     step() runs at the accepting edge, the slots only delay its result;
///   - a sof presented while the kernel needs_fit() is not taken: at that edge the fit starts
///     and runs kFitClocks clocks (in_ready low throughout), the new road taking effect at the
///     last one; the sof is taken from the next clock on. The pipeline keeps draining meanwhile.
template <typename Params>
class RoadModel {
 public:
  using Kernel = hls::road::Road<Params>;
  using in_type = typename Kernel::in_type;
  using out_type = typename Kernel::out_type;
  static constexpr int kLatency = hls::road::kLatency;
  static constexpr int kFitClocks = hls::road::kFitClocks;

  explicit RoadModel(const hls::road::RoadConfig& cfg) : k_(cfg) {}

  StreamOutputs<out_type> eval(bool in_valid, const in_type& in, bool out_ready) {
    StreamOutputs<out_type> o;
    o.out_valid = slots_[kLatency - 1].has_value();
    if (o.out_valid) o.out = *slots_[kLatency - 1];
    adv_ = !o.out_valid || out_ready;
    start_fit_ = busy_ == 0 && in_valid && k_.needs_fit(in);
    o.in_ready = adv_ && busy_ == 0 && !start_fit_;
    take_ = in_valid && o.in_ready;
    in_ = in;
    return o;
  }
  void tick() {
    if (busy_ > 0) {
      if (--busy_ == 0) k_.fit();
    } else if (start_fit_) {
      busy_ = kFitClocks;
    }
    if (!adv_) return;
    for (int i = kLatency - 1; i > 0; --i) slots_[i] = slots_[i - 1];
    slots_[0].reset();
    if (take_) slots_[0] = k_.step(in_);
  }

  Kernel& kernel() { return k_; }
  const Kernel& kernel() const { return k_; }

 private:
  Kernel k_;
  std::array<std::optional<out_type>, kLatency> slots_{};
  int busy_ = 0;
  bool adv_ = false, start_fit_ = false, take_ = false;
  in_type in_{};
};

}  // namespace scw::sim
