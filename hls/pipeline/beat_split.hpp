// SPDX-License-Identifier: Apache-2.0
// Beat split: a stream of P pixels per beat as one pixel per beat, at full output throughput.
#pragma once

#include "hls/common/beat.hpp"

namespace scw::hls::pipeline {

/// The twin of rtl_models/pipeline/scw_beat_split.sv. One register holds an input beat; its
/// pixels leave one per clock, pixel 0 first. The pixel-0 beat carries the input's sof, the
/// pixel-(P-1) beat its eol, the others neither. The register takes the next input beat in the
/// cycle its last pixel is taken, so a continuous input gives one output beat every clock.
///
/// The block changes rate (one input beat per P output beats), so it is written as the register
/// and its next-state function rather than as a per-beat step(): `out_valid()`, `out()` and
/// `in_ready()` are the combinational outputs, `clock()` the edge. sim::BeatSplitModel drives
/// it with the shared eval/tick interface. P = 1 is a plain stream register.
template <typename T, int P>
class BeatSplit {
 public:
  using in_type = Beat<T, P>;
  using out_type = Beat<T, 1>;

  /// Pixel `i` of `b` as a beat of its own (the flag rule above).
  static out_type pixel(const in_type& b, int i) {
    out_type o;
    o.px[0] = b.px[static_cast<std::size_t>(i)];
    o.sof = b.sof && i == 0;
    o.eol = b.eol && i == P - 1;
    return o;
  }

  /// Registered: never depends on out_ready.
  bool out_valid() const { return valid_; }
  out_type out() const { return pixel(reg_, index_); }
  /// Free, or handing over its last pixel this cycle.
  bool in_ready(bool out_ready) const { return !valid_ || (out_ready && index_ == P - 1); }

  /// The clock edge, with the cycle's inputs.
  void clock(bool in_valid, const in_type& in, bool out_ready) {
    const bool take = in_valid && in_ready(out_ready);
    const bool pop = valid_ && out_ready;
    if (take) {
      reg_ = in;
      index_ = 0;
      valid_ = true;
    } else if (pop) {
      if (index_ == P - 1) {
        valid_ = false;
      } else {
        ++index_;
      }
    }
  }

 private:
  in_type reg_{};
  int index_ = 0;  // the pixel presented: 0 .. P-1
  bool valid_ = false;
};

}  // namespace scw::hls::pipeline
