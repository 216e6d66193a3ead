// SPDX-License-Identifier: Apache-2.0
// The road kernel clocked as its RTL: a two-register pipeline under one enable, the fit between
// frames that holds the next sof, and the line each frame is gated with on a side output.
#pragma once

#include "hls/road/road.hpp"
#include "sim/core/cycle_model.hpp"
#include "sim/core/side_component.hpp"
#include "sim/models/pipeline_shell.hpp"

namespace scw::sim {

/// hls::road::Road as a cycle model of scw_road, clock for clock:
///   - the pipeline (kLatency slots) advances when its last slot is empty or read; the kernel's
///     step() runs at the accepting edge, the slots only delay its result;
///   - a sof presented while the kernel needs_fit() is not taken: at that edge the fit starts
///     and runs kFitClocks clocks (in_ready low throughout), the new road taking effect at the
///     last one; the sof is taken from the next clock on. The pipeline keeps draining meanwhile;
///   - the line output holds the line of the frame whose sof was taken last, from the next clock
///     until read; a sof is taken only when it is free or read in the same clock:
///       in_ready = adv && !busy && !start_fit && (!sof || !line_valid || line_ready).
/// With the three-argument eval (a one-output stream model) the line is always read, which
/// leaves the stream's timing as if the stage had no line output.
template <typename Params>
class RoadModel {
 public:
  using Kernel = hls::road::Road<Params>;
  using in_type = typename Kernel::in_type;
  using out_type = typename Kernel::out_type;
  using side_type = hls::road::Line;
  static constexpr int kLatency = hls::road::kLatency;
  static constexpr int kFitClocks = hls::road::kFitClocks;

  explicit RoadModel(const hls::road::RoadConfig& cfg) : k_(cfg) {}

  SideOutputs<out_type, side_type> eval(bool in_valid, const in_type& in, bool out_ready,
                                        bool line_ready) {
    SideOutputs<out_type, side_type> o;
    slots_.present(o);
    o.flag_valid = line_valid_;
    if (line_valid_) o.flag = line_;
    adv_ = slots_.enable(out_ready);
    start_fit_ = busy_ == 0 && in_valid && k_.needs_fit(in);
    o.in_ready = adv_ && busy_ == 0 && !start_fit_ && (!in.sof || !line_valid_ || line_ready);
    take_ = in_valid && o.in_ready;
    line_ready_ = line_ready;
    in_ = in;
    return o;
  }
  StreamOutputs<out_type> eval(bool in_valid, const in_type& in, bool out_ready) {
    const auto s = eval(in_valid, in, out_ready, true);
    StreamOutputs<out_type> o;
    o.in_ready = s.in_ready;
    o.out_valid = s.out_valid;
    o.out = s.out;
    return o;
  }
  void tick() {
    if (take_ && in_.sof) {
      line_valid_ = true;
      line_ = k_.line();
    } else if (line_ready_) {
      line_valid_ = false;
    }
    if (busy_ > 0) {
      if (--busy_ == 0) k_.fit();
    } else if (start_fit_) {
      busy_ = kFitClocks;
    }
    if (adv_) slots_.advance(take_, [this] { return k_.step(in_); });
  }

  Kernel& kernel() { return k_; }
  const Kernel& kernel() const { return k_; }

 private:
  Kernel k_;
  SlotRegister<out_type, kLatency> slots_;
  int busy_ = 0;
  bool adv_ = false, start_fit_ = false, take_ = false, line_ready_ = false;
  bool line_valid_ = false;
  hls::road::Line line_{};
  in_type in_{};
};

}  // namespace scw::sim
