// SPDX-License-Identifier: Apache-2.0
// A frame check (C++ model or Verilated RTL) between FIFOs: pixels in and out, flags out.
#pragma once

#include <string>
#include <utility>

#include "hls/pipeline/frame_check.hpp"
#include "sim/simulator.hpp"

namespace scw::sim {

/// Puts a FrameCheckModel or FrameCheckRtl between an input FIFO, an output FIFO and a flag
/// FIFO, as if the RTL block were wired to three scw_fifo instances: in_valid is "the input
/// FIFO has a beat", out_ready and flag_ready "the FIFO has space", all as of the start of the
/// cycle (as StreamComponent).
template <typename Model>
class FrameCheckComponent : public Component {
 public:
  using In = typename Model::in_type;
  using Flag = hls::Packet<hls::pipeline::FrameFlag>;

  FrameCheckComponent(std::string name, Model model, Fifo<In>& in, Fifo<In>& out,
                      Fifo<Flag>& flags)
      : Component(std::move(name)), model_(std::move(model)), in_(in), out_(out), flags_(flags) {
    connect_in(in_);
    connect_out(out_);
    connect_out(flags_);
  }

  void eval() override {
    const bool in_valid = in_.can_pop();
    const In beat = in_valid ? in_.front() : In{};
    const bool out_ready = out_.can_push();
    const bool flag_ready = flags_.can_push();
    const auto o = model_.eval(in_valid, beat, out_ready, flag_ready);
    if (in_valid && o.in_ready) in_.pop();
    if (o.out_valid && out_ready) out_.push(o.out);
    // One word per frame: every flag is a whole burst.
    if (o.flag_valid && flag_ready) flags_.push(Flag{o.flag, true});
  }
  void tick() override { model_.tick(); }

  Model& model() { return model_; }

 private:
  Model model_;
  Fifo<In>& in_;
  Fifo<In>& out_;
  Fifo<Flag>& flags_;
};

}  // namespace scw::sim
