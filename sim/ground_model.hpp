// SPDX-License-Identifier: Apache-2.0
// The ground-removal kernel clocked as its RTL: line buffer pipeline, then decision pipeline.
#pragma once

#include <array>
#include <optional>

#include "hls/ground/ground.hpp"
#include "sim/cycle_model.hpp"

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
    o.out_valid = dec_[kDecideLatency - 1].has_value();
    if (o.out_valid) o.out = *dec_[kDecideLatency - 1];
    dec_adv_ = !o.out_valid || out_ready;
    line_adv_ = !line_[kLineLatency - 1].has_value() || dec_adv_;
    o.in_ready = line_adv_;
    in_valid_ = in_valid;
    in_ = in;
    return o;
  }
  void tick() {
    // The decision takes the line buffer's last slot before the line buffer moves on (it moves
    // whenever the decision does).
    if (dec_adv_) {
      for (int i = kDecideLatency - 1; i > 0; --i) dec_[i] = dec_[i - 1];
      dec_[0].reset();
      if (line_[kLineLatency - 1]) dec_[0] = k_.decide(*line_[kLineLatency - 1]);
    }
    if (line_adv_) {
      for (int i = kLineLatency - 1; i > 0; --i) line_[i] = line_[i - 1];
      line_[0].reset();
      if (in_valid_) line_[0] = k_.window(in_);
    }
  }

  Kernel& kernel() { return k_; }
  const Kernel& kernel() const { return k_; }

 private:
  Kernel k_;
  std::array<std::optional<column_type>, kLineLatency> line_{};
  std::array<std::optional<out_type>, kDecideLatency> dec_{};
  bool line_adv_ = false, dec_adv_ = false, in_valid_ = false;
  in_type in_{};
};

}  // namespace scw::sim
