// SPDX-License-Identifier: Apache-2.0
// The pipeline's output word, {last, payload}: what scw_pipeline's out_data_o carries.
#pragma once

#include "hls/pipeline/pipeline_result.hpp"
#include "sim/words/pack.hpp"
#include "sim/words/warning_pack.hpp"

namespace scw::sim {

/// Payload, least significant first: the warning stage's frame result (199 bits,
/// warning_pack.hpp), input_error_left, input_error_right.
template <>
struct BeatLayout<hls::pipeline::PipelineResultPacket> {
  using beat_t = hls::pipeline::PipelineResultPacket;
  using frame_layout = BeatLayout<hls::warning::ResultPacket>;
  static constexpr int kFrameBits = frame_layout::kPayloadBits;
  static constexpr int kPayloadBits = kFrameBits + 2;  // 201
  static constexpr int kBits = kPayloadBits + 1;

  static Bits payload(const beat_t& b) {
    const Bits f = frame_layout::payload(hls::warning::ResultPacket{b.data.frame, b.last});
    Bits w(kPayloadBits);
    for (int i = 0; i < kFrameBits; ++i) w.set(i, 1, f.get(i, 1));
    w.set(kFrameBits, 1, b.data.input_error_left);
    w.set(kFrameBits + 1, 1, b.data.input_error_right);
    return w;
  }
  static beat_t from_payload(const Bits& w, bool last) {
    Bits f(kFrameBits);
    for (int i = 0; i < kFrameBits; ++i) f.set(i, 1, w.get(i, 1));
    beat_t b;
    b.data.frame = frame_layout::from_payload(f, last).data;
    b.data.input_error_left = w.get(kFrameBits, 1) != 0;
    b.data.input_error_right = w.get(kFrameBits + 1, 1) != 0;
    b.last = last;
    return b;
  }
};

}  // namespace scw::sim
