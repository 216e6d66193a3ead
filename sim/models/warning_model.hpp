// SPDX-License-Identifier: Apache-2.0
// The warning kernel clocked as a cycle model: object words -> frame results, with or without a
// road line per frame.
#pragma once

#include "hls/warning/warning.hpp"
#include "sim/core/join.hpp"
#include "sim/models/kernel_model.hpp"
#include "sim/words/labelling_pack.hpp"
#include "sim/words/warning_pack.hpp"

namespace scw::sim {

/// The warning stage's ready without a road input: its one pipeline enable,
/// !out_valid || out_ready (a config with road_height would wait for a line that never comes).
template <typename Params>
bool warning_ready(const hls::warning::Warning<Params>& k,
                   const typename hls::warning::Warning<Params>::in_type&, bool out_ready) {
  return k.in_ready(out_ready);
}

/// hls::warning::Warning as a one-input cycle model: its output register is the stage's output.
template <typename Params>
using WarningModel = KernelModel<hls::warning::Warning<Params>, &warning_ready<Params>>;

/// hls::warning::Warning with its road input as a join model (a: object words, b: road lines,
/// one a frame), as the pipeline wires it: the stage takes a line with each frame's first word.
template <typename Params>
class WarningRoadModel {
 public:
  using Kernel = hls::warning::Warning<Params>;
  using a_type = hls::labelling::LabelPacket;
  using b_type = hls::Packet<hls::warning::RoadLine>;
  using out_type = hls::warning::ResultPacket;

  explicit WarningRoadModel(const hls::warning::WarningConfig& cfg) : k_(cfg) {}

  JoinOutputs<out_type> eval(bool a_valid, const a_type& a, bool b_valid, const b_type& b,
                             bool out_ready) {
    JoinOutputs<out_type> o;
    o.a_ready = k_.in_ready(out_ready, b_valid);
    o.b_ready = k_.road_ready(a_valid, out_ready);
    o.out_valid = k_.out_valid();
    if (o.out_valid) o.out = k_.out();
    a_valid_ = a_valid;
    b_valid_ = b_valid;
    out_ready_ = out_ready;
    a_ = a;
    b_ = b;
    return o;
  }
  void tick() { k_.clock(a_valid_, a_, out_ready_, b_valid_, b_.data); }

  Kernel& kernel() { return k_; }
  const Kernel& kernel() const { return k_; }

 private:
  Kernel k_;
  bool a_valid_ = false, b_valid_ = false, out_ready_ = false;
  a_type a_{};
  b_type b_{};
};

}  // namespace scw::sim
