// SPDX-License-Identifier: Apache-2.0
// The frame check clocked as its RTL: a pass-through register plus a flag register.
#pragma once

#include "hls/pipeline/frame_check.hpp"
#include "sim/core/side_component.hpp"
#include "sim/models/pipeline_shell.hpp"

namespace scw::sim {

/// What a frame check presents in a cycle: the pixel path's handshake plus the flag output
/// (the C++ model and the RTL wrapper, sim/rtl/frame_check_rtl.hpp, both return it).
template <typename Out>
using FrameCheckOutputs = SideOutputs<Out, hls::pipeline::FrameFlag>;

/// hls::pipeline::FrameCheck clocked as scw_frame_check, cycle for cycle. The pixel path is one
/// register under adv = !out_valid || out_ready; the flag is one register. A beat whose
/// acceptance emits a flag also needs the flag register free or being read:
///   in_ready = adv && (!emits_flag(in) || !flag_valid || flag_ready).
/// `eval` settles outputs for the given inputs and changes no state; `tick` is the clock edge
/// with the inputs of the last `eval`.
template <int P, int MaxWidthPx, int MaxHeight>
class FrameCheckModel {
 public:
  using Kernel = hls::pipeline::FrameCheck<P, MaxWidthPx, MaxHeight>;
  using params = typename Kernel::params;
  using in_type = typename Kernel::in_type;
  using out_type = typename Kernel::out_type;
  using flag_type = typename Kernel::flag_type;
  using side_type = hls::pipeline::FrameFlag;  // SideComponent's side FIFO carries its packets

  explicit FrameCheckModel(const hls::pipeline::FrameCheckConfig& cfg) : k_(cfg) {}

  FrameCheckOutputs<out_type> eval(bool in_valid, const in_type& in, bool out_ready,
                                   bool flag_ready) {
    adv_ = out_.enable(out_ready);
    const bool flag_free = !flag_valid_ || flag_ready;
    FrameCheckOutputs<out_type> o;
    o.in_ready = adv_ && (!k_.emits_flag(in) || flag_free);
    out_.present(o);
    o.flag_valid = flag_valid_;
    if (flag_valid_) o.flag = flag_;
    take_ = in_valid && o.in_ready;
    flag_pop_ = flag_valid_ && flag_ready;
    in_ = in;
    return o;
  }

  void tick() {
    if (flag_pop_) flag_valid_ = false;
    if (take_) {
      hls::pipeline::FrameFlag f;
      if (k_.step(in_, f)) {
        flag_ = f;
        flag_valid_ = true;
      }
    }
    if (adv_) out_.advance(take_, [this] { return in_; });
  }

  Kernel& kernel() { return k_; }
  const Kernel& kernel() const { return k_; }

 private:
  Kernel k_;
  SlotRegister<out_type, 1> out_;  // the pixel path's one register
  bool flag_valid_ = false;
  hls::pipeline::FrameFlag flag_{};
  // The last eval's decisions, applied at the edge.
  bool adv_ = false;
  bool take_ = false;
  bool flag_pop_ = false;
  in_type in_{};
};

}  // namespace scw::sim
