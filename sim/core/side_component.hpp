// SPDX-License-Identifier: Apache-2.0
// A stage with a one-word-per-frame side output (the frame check's flag, the road stage's line)
// between FIFOs: beats in and out, side words out.
#pragma once

#include <string>
#include <utility>

#include "hls/common/beat.hpp"
#include "sim/core/simulator.hpp"

namespace scw::sim {

/// What such a stage presents in a cycle: the stream handshake plus the side output. Two
/// outputs, so not StreamOutputs; a C++ model and its RTL wrapper both return it.
template <typename Out, typename Side>
struct SideOutputs {
  bool in_ready = false;
  bool out_valid = false;
  Out out{};
  bool flag_valid = false;  // the side word (named as the frame check's flag port)
  Side flag{};
};

/// Puts a model with `eval(in_valid, in, out_ready, side_ready) -> SideOutputs` and `tick()`
/// between an input FIFO, an output FIFO and a side FIFO, as if the RTL block were wired to three
/// scw_fifo instances: in_valid is "the input FIFO has a beat", out_ready and side_ready "the
/// FIFO has space", all as of the start of the cycle (as StreamComponent).
template <typename Model>
class SideComponent : public Component {
 public:
  using In = typename Model::in_type;
  using Out = typename Model::out_type;
  using Side = hls::Packet<typename Model::side_type>;

  SideComponent(std::string name, Model model, Fifo<In>& in, Fifo<Out>& out, Fifo<Side>& side)
      : Component(std::move(name)), model_(std::move(model)), in_(in), out_(out), side_(side) {
    connect_in(in_);
    connect_out(out_);
    connect_out(side_);
  }

  void eval() override {
    const bool in_valid = in_.can_pop();
    const In beat = in_valid ? in_.front() : In{};
    const bool out_ready = out_.can_push();
    const bool side_ready = side_.can_push();
    const auto o = model_.eval(in_valid, beat, out_ready, side_ready);
    if (in_valid && o.in_ready) in_.pop();
    if (o.out_valid && out_ready) out_.push(o.out);
    // One word per frame: every side word is a whole burst.
    if (o.flag_valid && side_ready) side_.push(Side{o.flag, true});
  }
  void tick() override { model_.tick(); }

  Model& model() { return model_; }

 private:
  Model model_;
  Fifo<In>& in_;
  Fifo<Out>& out_;
  Fifo<Side>& side_;
};

}  // namespace scw::sim
