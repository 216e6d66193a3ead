// SPDX-License-Identifier: Apache-2.0
// The beat split clocked as its RTL: the cycle model (eval/tick) of scw_beat_split.
#pragma once

#include "hls/pipeline/beat_split.hpp"
#include "sim/cycle_model.hpp"

namespace scw::sim {

/// hls::pipeline::BeatSplit clocked as scw_beat_split: same in_ready, out_valid and out data
/// every cycle. `eval` only settles outputs and remembers the inputs; `tick` is the edge.
template <typename T, int P>
class BeatSplitModel {
 public:
  using Kernel = hls::pipeline::BeatSplit<T, P>;
  using in_type = typename Kernel::in_type;
  using out_type = typename Kernel::out_type;

  StreamOutputs<out_type> eval(bool in_valid, const in_type& in, bool out_ready) {
    in_valid_ = in_valid;
    in_ = in;
    out_ready_ = out_ready;
    StreamOutputs<out_type> o;
    o.in_ready = k_.in_ready(out_ready);
    o.out_valid = k_.out_valid();
    if (o.out_valid) o.out = k_.out();
    return o;
  }
  void tick() { k_.clock(in_valid_, in_, out_ready_); }

  const Kernel& kernel() const { return k_; }

 private:
  Kernel k_;
  bool in_valid_ = false;
  bool out_ready_ = false;
  in_type in_{};
};

}  // namespace scw::sim
