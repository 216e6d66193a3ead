// SPDX-License-Identifier: Apache-2.0
// The rectify kernel clocked as its RTL pipeline: a join model (raw pixels, map) -> pixels.
#pragma once

#include "hls/rectify/rectify.hpp"
#include "sim/core/join.hpp"
#include "sim/models/pipeline_shell.hpp"

namespace scw::sim {

/// hls::rectify::Rectify behind Latency register stages under one enable, like
/// PipelineShell: the reader's beat is computed when its map beat is accepted and presented
/// Latency cycles later; the writer runs on its own. `pending` (the writer's look at the
/// pipeline) is "the first stage holds the last beat of an output row".
template <typename Params>
class RectifyModel {
 public:
  using Kernel = hls::rectify::Rectify<Params>;
  using a_type = typename Kernel::raw_type;
  using b_type = typename Kernel::map_type;
  using out_type = typename Kernel::out_type;
  static constexpr int kLatency = Params::kLatency;

  explicit RectifyModel(const hls::rectify::RectifyConfig& cfg) : k_(cfg) {}

  JoinOutputs<out_type> eval(bool a_valid, const a_type& a, bool b_valid, const b_type& b,
                             bool out_ready) {
    JoinOutputs<out_type> o;
    slots_.present(o);
    advance_ = slots_.enable(out_ready);
    pending_ = slots_.first().has_value() && slots_.first()->eol;
    o.a_ready = k_.raw_ready(pending_);
    o.b_ready = k_.map_ready(advance_);
    a_take_ = a_valid && o.a_ready;
    b_take_ = b_valid && o.b_ready;
    a_ = a;
    b_ = b;
    return o;
  }
  void tick() {
    const auto e = k_.clock(pending_, a_take_, a_, advance_, b_take_, b_);
    if (advance_) slots_.advance(e.valid, [&e] { return e.beat; });
  }

  Kernel& kernel() { return k_; }
  const Kernel& kernel() const { return k_; }

 private:
  Kernel k_;
  SlotRegister<out_type, kLatency> slots_;
  bool advance_ = false, pending_ = false, a_take_ = false, b_take_ = false;
  a_type a_{};
  b_type b_{};
};

}  // namespace scw::sim
