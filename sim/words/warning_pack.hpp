// SPDX-License-Identifier: Apache-2.0
// The warning stage's output word, {last, payload}: what the RTL's out_data_o carries and the
// golden vectors store.
#pragma once

#include <cstdint>

#include "hls/warning/warning_params.hpp"
#include "sim/words/pack.hpp"

namespace scw::sim {

/// Payload, least significant first: severity (2 bits), in_tunnel, too_close, tile_overflow,
/// object_overflow, stream_error (1 each), objects, obstacles, index (16 each), distance_mm
/// (32, two's complement), closest_x, closest_y, d_max, x_min, x_max, y_min, y_max (16 each).
template <>
struct BeatLayout<hls::Packet<hls::warning::FrameResult>> {
  using beat_t = hls::Packet<hls::warning::FrameResult>;
  static constexpr int kPayloadBits = 2 + 5 + 3 * 16 + 32 + 7 * 16;  // 199
  static constexpr int kBits = kPayloadBits + 1;

  static Bits payload(const beat_t& b) {
    Bits w(kPayloadBits);
    const auto& r = b.data;
    w.set(0, 2, static_cast<std::uint64_t>(r.severity));
    int at = 2;
    for (bool f : {r.in_tunnel, r.too_close, r.tile_overflow, r.object_overflow, r.stream_error})
      w.set(at++, 1, f);
    for (std::uint16_t v : {r.objects, r.obstacles, r.index}) {
      w.set(at, 16, v);
      at += 16;
    }
    w.set(at, 32, static_cast<std::uint32_t>(r.distance_mm));
    at += 32;
    for (std::uint16_t v : {r.closest_x, r.closest_y, r.d_max, r.x_min, r.x_max, r.y_min, r.y_max}) {
      w.set(at, 16, v);
      at += 16;
    }
    return w;
  }
  static beat_t from_payload(const Bits& w, bool last) {
    beat_t b;
    b.last = last;
    auto& r = b.data;
    r.severity = static_cast<hls::warning::Severity>(w.get(0, 2));
    int at = 2;
    for (bool* f : {&r.in_tunnel, &r.too_close, &r.tile_overflow, &r.object_overflow,
                    &r.stream_error})
      *f = w.get(at++, 1) != 0;
    for (std::uint16_t* v : {&r.objects, &r.obstacles, &r.index}) {
      *v = static_cast<std::uint16_t>(w.get(at, 16));
      at += 16;
    }
    r.distance_mm = static_cast<std::int32_t>(static_cast<std::uint32_t>(w.get(at, 32)));
    at += 32;
    for (std::uint16_t* v : {&r.closest_x, &r.closest_y, &r.d_max, &r.x_min, &r.x_max, &r.y_min,
                             &r.y_max}) {
      *v = static_cast<std::uint16_t>(w.get(at, 16));
      at += 16;
    }
    return b;
  }
};

}  // namespace scw::sim
