// SPDX-License-Identifier: Apache-2.0
// The labelling kernel clocked as a one-in one-out stream model: disparities -> object words.
#pragma once

#include "hls/labelling/labelling.hpp"
#include "sim/cycle_model.hpp"
#include "sim/labelling_pack.hpp"

namespace scw::sim {

/// hls::labelling::Labelling as a cycle model: its output register is the stage's output.
template <typename Params>
class LabellingModel {
 public:
  using Kernel = hls::labelling::Labelling<Params>;
  using in_type = typename Kernel::in_type;
  using out_type = typename Kernel::out_type;

  explicit LabellingModel(const hls::labelling::LabellingConfig& cfg) : k_(cfg) {}

  StreamOutputs<out_type> eval(bool in_valid, const in_type& in, bool out_ready) {
    StreamOutputs<out_type> o;
    o.in_ready = k_.in_ready(in.sof);
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
