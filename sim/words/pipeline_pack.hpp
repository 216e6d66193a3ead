// SPDX-License-Identifier: Apache-2.0
// The pipeline's output word, {last, payload}: what scw_pipeline's out_data_o carries.
#pragma once

#include "hls/pipeline/pipeline_result.hpp"
#include "sim/words/pack.hpp"
#include "sim/words/warning_pack.hpp"

namespace scw::sim {

/// Payload, least significant first: the warning stage's frame result (warning_word's table),
/// input_error_left, input_error_right.
template <>
struct BeatLayout<hls::pipeline::PipelineResultPacket> {
  using beat_t = hls::pipeline::PipelineResultPacket;
  static constexpr int kFrameBits = warning_word::kPayloadBits;
  static constexpr int kPayloadBits = kFrameBits + 2;
  static constexpr int kBits = kPayloadBits + 1;

  static Bits payload(const beat_t& b) {
    Bits w(kPayloadBits);
    words::pack_fields(w, 0, b.data.frame, warning_word::kResultFields);
    w.set(kFrameBits, 1, b.data.input_error_left);
    w.set(kFrameBits + 1, 1, b.data.input_error_right);
    return w;
  }
  static beat_t from_payload(const Bits& w, bool last) {
    beat_t b;
    words::unpack_fields(w, 0, b.data.frame, warning_word::kResultFields);
    b.data.input_error_left = w.get(kFrameBits, 1) != 0;
    b.data.input_error_right = w.get(kFrameBits + 1, 1) != 0;
    b.last = last;
    return b;
  }
};

}  // namespace scw::sim
