// SPDX-License-Identifier: Apache-2.0
// The result merge (frame result + two input flags -> pipeline result) in the simulator: the
// Verilated scw_result_merge as a model of the C++ twin's shape, and their component.
#pragma once

#include <string>
#include <utility>

#include "hls/pipeline/pipeline_result.hpp"
#include "sim/core/simulator.hpp"
#include "sim/rtl/rtl_adapter.hpp"
#include "sim/words/pipeline_pack.hpp"

namespace scw::sim {

/// `VM` is a Verilated scw_result_merge module class: built for the frame result's width?
template <typename VM>
constexpr bool result_merge_params_match() {
  return VM::ResW == BeatLayout<hls::warning::ResultPacket>::kPayloadBits;
}

/// scw_result_merge's result group res_valid_i/res_ready_o/res_data_i/res_last_i, bound as every
/// stage's input.
SCW_IN_PORTS(ResultMergeResPorts, res);

/// `VM` is a Verilated scw_result_merge; same eval/tick as hls::pipeline::ResultMerge.
template <typename VM>
class ResultMergeRtl : public RtlAdapter<VM> {
 public:
  using Outputs = hls::pipeline::ResultMerge::Outputs;

  explicit ResultMergeRtl(const std::string& name) : RtlAdapter<VM>(name) {}

  Outputs eval(bool res_valid, const hls::warning::ResultPacket& res, bool left_valid,
               const hls::pipeline::FlagPacket& left, bool right_valid,
               const hls::pipeline::FlagPacket& right, bool out_ready) {
    VM& m = this->dut();
    ResultMergeResPorts::drive(m, res_valid, res);
    m.left_valid_i = left_valid;
    m.left_error_i = left.data.error;
    m.right_valid_i = right_valid;
    m.right_error_i = right.data.error;
    m.out_ready_i = out_ready;
    // The merge takes its three inputs together, on res_ready_o.
    auto o = settle_out<Outputs>(this->harness(),
                                 QuietKey::bits(res_valid, left_valid, right_valid, out_ready),
                                 [&](const VM& d) {
                                   const bool moved = d.res_ready_o || (d.out_valid_o && out_ready);
                                   return moved ? QuietKey::kBusy : QuietKey::bits(d.out_valid_o);
                                 });
    o.in_ready = ResultMergeResPorts::ready(m);
    return o;
  }
};

/// Puts a merge model between the result FIFO, the two flag FIFOs and the output FIFO.
template <typename Model>
class MergeComponent : public Component {
 public:
  using Res = hls::warning::ResultPacket;
  using Flag = hls::pipeline::FlagPacket;
  using Out = hls::pipeline::PipelineResultPacket;

  MergeComponent(std::string name, Model model, Fifo<Res>& res, Fifo<Flag>& left,
                 Fifo<Flag>& right, Fifo<Out>& out)
      : Component(std::move(name)), model_(std::move(model)), res_(res), left_(left),
        right_(right), out_(out) {
    connect_in(res_);
    connect_in(left_);
    connect_in(right_);
    connect_out(out_);
  }

  void eval() override {
    const bool rv = res_.can_pop(), lv = left_.can_pop(), fv = right_.can_pop();
    const bool out_ready = out_.can_push();
    const auto o = model_.eval(rv, rv ? res_.front() : Res{}, lv, lv ? left_.front() : Flag{},
                               fv, fv ? right_.front() : Flag{}, out_ready);
    if (o.in_ready) {
      res_.pop();
      left_.pop();
      right_.pop();
    }
    if (o.out_valid && out_ready) out_.push(o.out);
  }
  void tick() override { model_.tick(); }

 private:
  Model model_;
  Fifo<Res>& res_;
  Fifo<Flag>& left_;
  Fifo<Flag>& right_;
  Fifo<Out>& out_;
};

}  // namespace scw::sim
