// SPDX-License-Identifier: Apache-2.0
// The pipeline's one output word per frame: the warning stage's result plus the input checks'
// flags, and the block that joins them (twin of rtl_models/pipeline/scw_result_merge.sv).
#pragma once

#include "hls/common/beat.hpp"
#include "hls/common/stream.hpp"
#include "hls/pipeline/frame_check.hpp"
#include "hls/warning/warning_params.hpp"

namespace scw::hls::pipeline {

/// The rectifiers repair a broken input frame (they always emit whole frames), so the warning
/// stage cannot see it; the frame checks at the inputs can, and their flags travel beside the
/// frame to this word.
struct PipelineResult {
  warning::FrameResult frame;
  bool input_error_left = false;   // the left camera's frame broke the geometry (frame_check)
  bool input_error_right = false;  // the right camera's

  friend bool operator==(const PipelineResult& a, const PipelineResult& b) {
    return a.frame == b.frame && a.input_error_left == b.input_error_left &&
           a.input_error_right == b.input_error_right;
  }
  friend bool operator!=(const PipelineResult& a, const PipelineResult& b) { return !(a == b); }
};

using PipelineResultPacket = Packet<PipelineResult>;
using FlagPacket = Packet<FrameFlag>;

/// Joins frame k's warning result with frame k's two input flags. One output register under
/// one enable (adv = !out_valid || out_ready); all three inputs are taken together when all are
/// valid and the register advances.
class ResultMerge {
 public:
  struct Outputs {
    bool in_ready = false;  // the same for all three inputs
    bool out_valid = false;
    PipelineResultPacket out{};
  };

  Outputs eval(bool res_valid, const warning::ResultPacket& res, bool left_valid,
               const FlagPacket& left, bool right_valid, const FlagPacket& right,
               bool out_ready) {
    Outputs o;
    o.out_valid = valid_;
    o.out = out_;
    const bool adv = !valid_ || out_ready;
    take_ = adv && res_valid && left_valid && right_valid;
    o.in_ready = take_;
    adv_ = adv;
    next_.data.frame = res.data;
    next_.data.input_error_left = left.data.error;
    next_.data.input_error_right = right.data.error;
    next_.last = res.last;
    return o;
  }
  void tick() {
    if (!adv_) return;
    valid_ = take_;
    if (take_) out_ = next_;
  }

 private:
  bool valid_ = false, adv_ = false, take_ = false;
  PipelineResultPacket out_{}, next_{};
};

// The loop label names the loop in HLS reports; g++ would call it unused.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-label"
/// `frames` frame results joined with their two input flags, no output stalls; each input waits
/// in a look-ahead register until all three are there. Stops when `frames` results have left or
/// after `max_clocks`; returns how many left.
template <typename ResIn, typename FlagIn, typename Out>
int merge_frame(ResultMerge& m, ResIn& res, FlagIn& left, FlagIn& right, Out& out, int frames,
                long max_clocks) {
  Lookahead<warning::ResultPacket> r;
  Lookahead<FlagPacket> l, f;
  int written = 0;
loop_clock:
  for (long c = 0; c < max_clocks && written < frames; ++c) {
    // clang-format off
#pragma HLS PIPELINE II=1
    // clang-format on
    r.fill(res);
    l.fill(left);
    f.fill(right);
    const auto o = m.eval(r.valid, r.beat, l.valid, l.beat, f.valid, f.beat, true);
    if (o.in_ready) {
      r.take();
      l.take();
      f.take();
    }
    m.tick();
    if (o.out_valid) {
      out.write(o.out);
      ++written;
    }
  }
  return written;
}
#pragma GCC diagnostic pop

}  // namespace scw::hls::pipeline
