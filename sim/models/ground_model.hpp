// SPDX-License-Identifier: Apache-2.0
// The ground-removal kernel clocked as its RTL: line buffer pipeline, then decision pipeline.
#pragma once

#include "hls/ground/ground.hpp"
#include "sim/core/cycle_model.hpp"
#include "sim/models/pipeline_shell.hpp"

namespace scw::sim {

/// hls::ground::Ground as a cycle model of scw_ground: two pipelines, each under one enable as
/// sim::PipelineShell (in_ready = !out_valid || out_ready). The line buffer's (kLineLatency
/// slots) computes window() when it accepts a beat, the decision's (kDecideLatency slots)
/// decide() when it takes the window; the line buffer's out_ready is the decision's enable, so a
/// bubble in the line buffer's last slot is filled while the decision waits, as in the RTL.
template <typename Params>
class GroundModel {
 public:
  using Kernel = hls::ground::Ground<Params>;
  using in_type = typename Kernel::in_type;
  using out_type = typename Kernel::out_type;
  using column_type = typename Kernel::column_type;
  static constexpr int kLineLatency = Params::kLineLatency;
  static constexpr int kDecideLatency = hls::ground::kDecideLatency;
  static constexpr int kLatency = Params::kLatency;
  static_assert(kLineLatency + kDecideLatency == kLatency, "the two pipelines make the stage");

  explicit GroundModel(const hls::ground::GroundConfig& cfg) : k_(cfg) {}

  StreamOutputs<out_type> eval(bool in_valid, const in_type& in, bool out_ready) {
    StreamOutputs<out_type> o;
    dec_.present(o);
    dec_adv_ = dec_.enable(out_ready);
    line_adv_ = line_.enable(dec_adv_);
    o.in_ready = line_adv_;
    in_valid_ = in_valid;
    in_ = in;
    return o;
  }
  void tick() {
    // The decision takes the line buffer's last slot before the line buffer moves on (it moves
    // whenever the decision does).
    if (dec_adv_) dec_.advance(line_.out_valid(), [this] { return k_.decide(line_.out()); });
    if (line_adv_) line_.advance(in_valid_, [this] { return k_.window(in_); });
  }

  Kernel& kernel() { return k_; }
  const Kernel& kernel() const { return k_; }

 private:
  Kernel k_;
  SlotRegister<column_type, kLineLatency> line_;
  SlotRegister<out_type, kDecideLatency> dec_;
  bool line_adv_ = false, dec_adv_ = false, in_valid_ = false;
  in_type in_{};
};

}  // namespace scw::sim
