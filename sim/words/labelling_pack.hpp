// SPDX-License-Identifier: Apache-2.0
// The labelling stage's output word, {last, payload}: what the RTL's out_data_o carries and the
// golden vectors store.
#pragma once

#include <cstdint>

#include "hls/labelling/labelling_params.hpp"
#include "sim/words/pack.hpp"

namespace scw::sim {

/// Payload, least significant first: is_status (1 bit), then for an object area (32), x_min,
/// x_max, y_min, y_max, d_min, d_max, closest_x, closest_y, first_x, first_y (16 each),
/// m10, m01, m20, m11, m02, m30, m21, m12, m03, sum_d, sum_dd (64 each); for the status word
/// objects (32),
/// tile_overflow, object_overflow, stream_error (1 each), the rest zero.
template <>
struct BeatLayout<hls::Packet<hls::labelling::LabelWord>> {
  using beat_t = hls::Packet<hls::labelling::LabelWord>;
  static constexpr int kPayloadBits = 1 + 32 + 10 * 16 + 11 * 64;  // 897
  static constexpr int kBits = kPayloadBits + 1;

  static Bits payload(const beat_t& b) {
    Bits w(kPayloadBits);
    const auto& d = b.data;
    w.set(0, 1, d.is_status);
    if (d.is_status) {
      w.set(1, 32, d.status.objects);
      w.set(33, 1, d.status.tile_overflow);
      w.set(34, 1, d.status.object_overflow);
      w.set(35, 1, d.status.stream_error);
      return w;
    }
    const auto& o = d.object;
    w.set(1, 32, o.area);
    int at = 33;
    for (std::uint16_t v : {o.x_min, o.x_max, o.y_min, o.y_max, o.d_min, o.d_max, o.closest_x,
                            o.closest_y, o.first_x, o.first_y}) {
      w.set(at, 16, v);
      at += 16;
    }
    for (std::uint64_t v :
         {o.m10, o.m01, o.m20, o.m11, o.m02, o.m30, o.m21, o.m12, o.m03, o.sum_d, o.sum_dd}) {
      w.set(at, 64, v);
      at += 64;
    }
    return w;
  }
  static beat_t from_payload(const Bits& w, bool last) {
    beat_t b;
    b.last = last;
    auto& d = b.data;
    d.is_status = w.get(0, 1) != 0;
    if (d.is_status) {
      d.status.objects = static_cast<std::uint32_t>(w.get(1, 32));
      d.status.tile_overflow = w.get(33, 1) != 0;
      d.status.object_overflow = w.get(34, 1) != 0;
      d.status.stream_error = w.get(35, 1) != 0;
      return b;
    }
    auto& o = d.object;
    o.area = static_cast<std::uint32_t>(w.get(1, 32));
    int at = 33;
    for (std::uint16_t* v : {&o.x_min, &o.x_max, &o.y_min, &o.y_max, &o.d_min, &o.d_max,
                             &o.closest_x, &o.closest_y, &o.first_x, &o.first_y}) {
      *v = static_cast<std::uint16_t>(w.get(at, 16));
      at += 16;
    }
    for (std::uint64_t* v : {&o.m10, &o.m01, &o.m20, &o.m11, &o.m02, &o.m30, &o.m21, &o.m12,
                             &o.m03, &o.sum_d, &o.sum_dd}) {
      *v = w.get(at, 64);
      at += 64;
    }
    return b;
  }
};

}  // namespace scw::sim
