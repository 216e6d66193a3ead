// SPDX-License-Identifier: Apache-2.0
// Warning kernel: the labelling stage's object table in, one frame result out, clock by clock as
// the RTL pipeline does it (docs/warning.md).
#pragma once

#include <array>
#include <stdexcept>
#include <string>

#include "hls/common/stream.hpp"
#include "hls/labelling/labelling_params.hpp"
#include "hls/warning/warning_params.hpp"

namespace scw::hls::warning {

/// Throws std::invalid_argument naming the field if `cfg` does not fit a stage built with
/// `Params`.
template <typename Params>
void check_config([[maybe_unused]] const WarningConfig& cfg) {
#ifndef __SYNTHESIS__  // the host's check: a synthesised top trusts its registers
  auto fail = [](const std::string& m) { throw std::invalid_argument("warning: " + m); };
  if (cfg.baseline_q8 == 0 || cfg.baseline_q8 >= (1u << 20))
    fail("baseline must be above 0 and below 4096 mm (Q12.8 in 20 bits)");
  if (cfg.focal_q4 == 0) fail("focal length must be above 0 px");
  if (cfg.d_limit_q4 < 16 || cfg.d_limit_q4 > Params::kTableSize)
    fail("disparity limit " + std::to_string(cfg.d_limit_q4 / 16.0) + " px outside 1 .. " +
         std::to_string(Params::kMaxDisparityPx) + " px (this build's reciprocal table)");
  if (cfg.high_mm > cfg.medium_mm) fail("the high threshold lies beyond the medium one");
  if (cfg.rule != DistanceRule::kClosest && cfg.rule != DistanceRule::kSpread)
    fail("distance rule " + std::to_string(static_cast<int>(cfg.rule)) +
         " unknown (0 closest, 1 spread)");
#endif
}

/// The stage. One pipeline enable (`en = !out_valid || out_ready`): a word taken at a clock
/// edge leaves the kLatency - 1 pipeline registers kLatency - 1 edges later and is folded into
/// the frame's result; the word that closes the frame loads the output register on the same
/// edge, so its result shows kLatency clocks after it was taken. With cfg.road_height the
/// first word of each frame (the first after reset or after a `last`) is taken together with a
/// road line from the road input, and waits for one:
///   in_ready   = en && (!first || road_valid)
///   road_ready = en && first && in_valid
/// Without it the road input is never read.
template <typename Params>
class Warning {
 public:
  using in_type = labelling::LabelPacket;
  using out_type = ResultPacket;

  explicit Warning(const WarningConfig& cfg) : cfg_(cfg) { check_config<Params>(cfg); }

  // ---- what the ports show this clock ----
  bool in_ready(bool out_ready, bool road_valid = false) const {
    return (!out_valid_ || out_ready) && (!needs_road() || road_valid);
  }
  bool road_ready(bool in_valid, bool out_ready) const {
    return (!out_valid_ || out_ready) && needs_road() && in_valid;
  }
  bool out_valid() const { return out_valid_; }
  const out_type& out() const { return out_; }
  const WarningConfig& config() const { return cfg_; }

  /// One clock edge; `road_valid` and `road` are the road input's (cfg.road_height).
  void clock(bool in_valid, const in_type& in, bool out_ready, bool road_valid = false,
             const RoadLine& road = {}) {
    const bool take = in_valid && in_ready(out_ready, road_valid);
    if (out_valid_ && out_ready) out_valid_ = false;
    const bool enable = !out_valid_ || out_ready;
    if (!enable) return;
    // The stage that leaves the pipeline is folded (out_valid_ is low here when it closes a
    // frame, since enable held).
    const Slot& last = pipe_[kStages - 1];
    if (last.valid) fold(last);
    for (int i = kStages - 1; i > 0; --i) pipe_[i] = pipe_[i - 1];
    pipe_[0] = Slot{};
    if (take) {
      if (needs_road()) road_ = road;
      first_ = in.last;
      pipe_[0].valid = true;
      pipe_[0].word = in.data;
      pipe_[0].last = in.last;
      if (!in.data.is_status) pipe_[0].eval = evaluate<Params>(in.data.object, cfg_, road_);
    }
  }

 private:
  static constexpr int kStages = kLatency - 1;
  struct Slot {
    bool valid = false;
    bool last = false;
    labelling::LabelWord word;
    ObjectEval eval;
  };

  bool needs_road() const { return cfg_.road_height && first_; }

  void fold(const Slot& s) {
    if (!s.word.is_status) {
      const ObjectEval& e = s.eval;
      if (e.obstacle) {
        ++acc_.obstacles;
        if (!have_best_ || decides_over(e, best_)) {
          have_best_ = true;
          best_ = e;
          acc_.index = acc_.objects;
          acc_.severity = e.severity;
          acc_.in_tunnel = e.in_tunnel;
          acc_.too_close = e.too_close;
          acc_.distance_mm = e.distance_mm;
          const auto& o = s.word.object;
          acc_.closest_x = o.closest_x;
          acc_.closest_y = o.closest_y;
          acc_.d_max = o.d_max;
          acc_.x_min = o.x_min;
          acc_.x_max = o.x_max;
          acc_.y_min = o.y_min;
          acc_.y_max = o.y_max;
        }
      }
      ++acc_.objects;
    }
    if (!s.word.is_status && !s.last) return;
    // The frame closes: on its status word, or on a `last` without one (a broken table).
    FrameResult r = acc_;
    if (s.word.is_status) {
      const auto& st = s.word.status;
      r.tile_overflow = st.tile_overflow;
      r.object_overflow = st.object_overflow;
      r.stream_error = st.stream_error || !s.last || st.objects != acc_.objects;
    } else {
      r.stream_error = true;
    }
    out_.data = r;
    out_.last = true;
    out_valid_ = true;
    acc_ = FrameResult{};
    have_best_ = false;
  }

  WarningConfig cfg_;
  std::array<Slot, kStages> pipe_{};
  FrameResult acc_;
  ObjectEval best_;
  bool have_best_ = false;
  bool out_valid_ = false;
  out_type out_{};
  bool first_ = true;  // the next word starts a frame
  RoadLine road_{};    // the frame's road (road_height)
};

// The loop label names the loop in HLS reports; g++ would call it unused.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-label"
/// Object tables through the stage with no output stalls: `frames` frames of words from `in`
/// (each closed by its status word with `last`), one result per frame to `out`, in order; returns
/// how many. With cfg.road_height, `roads` holds one road line a frame, taken with each frame's
/// first word. Word and line wait in look-ahead registers, so the stage sees them before taking
/// them (the road decides whether a word is taken). The loop runs kLatency clocks past the last
/// frame's status word so the last result leaves, or stops after `max_clocks`. What an HLS tool
/// synthesises as the stage's top: the ports are hls::stream (or ArrayIn / ArrayOut).
template <typename Params, typename In, typename Out, typename Roads, if_port<Out> = 0>
int warning_frame(Warning<Params>& w, In& in, int frames, Out& out, Roads& roads,
                  long max_clocks) {
  // clang-format off
#pragma HLS INTERFACE axis port=in
#pragma HLS INTERFACE axis port=out
#pragma HLS INTERFACE axis port=roads
#pragma HLS INTERFACE s_axilite port=frames
#pragma HLS INTERFACE s_axilite port=max_clocks
#pragma HLS INTERFACE s_axilite port=return
  // clang-format on
  Lookahead<labelling::LabelPacket> word;
  Lookahead<RoadLine> road;
  int results = 0, closed = 0, tail = 0;
loop_clock:
  for (long c = 0; c < max_clocks && tail < kLatency; ++c) {
    // clang-format off
#pragma HLS PIPELINE II=1
    // clang-format on
    if (closed == frames) ++tail;
    if (closed < frames) word.fill(in);
    road.fill(roads);
    const bool take = word.valid && w.in_ready(true, road.valid);
    const bool take_road = road.valid && w.road_ready(word.valid, true);
    w.clock(word.valid, word.beat, true, road.valid, road.beat);
    if (take_road) road.take();
    if (take) {
      closed += word.beat.last ? 1 : 0;
      word.take();
    }
    if (w.out_valid()) {
      out.write(w.out());
      ++results;
    }
  }
  return results;
}
#pragma GCC diagnostic pop

/// The frame function over arrays (tests): `n` words, whole frames; `roads` may be null (no road
/// input), else it holds one line a frame.
template <typename Params>
int warning_frame(Warning<Params>& w, const labelling::LabelPacket* in, int n, ResultPacket* out,
                  const RoadLine* roads = nullptr) {
  int frames = 0;
  for (int i = 0; i < n; ++i) frames += in[i].last ? 1 : 0;
  ArrayIn<labelling::LabelPacket> i(in, n);
  ArrayOut<ResultPacket> o(out);
  ArrayIn<RoadLine> r(roads, frames);
  return warning_frame(w, i, frames, o, r, static_cast<long>(n) + kLatency);
}

}  // namespace scw::hls::warning
