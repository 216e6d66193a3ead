// SPDX-License-Identifier: Apache-2.0
// The warning stage's output word, {last, payload}: what the RTL's out_data_o carries and the
// golden vectors store. Its fields are listed once, in kResultFields: packing, unpacking and
// the vector sets' layout JSON and CSV columns walk it. The widths are rtl_models/common/
// scw_pkg.sv's (scw_pkg.hpp is generated from it), where the RTL's word is warning_result_t;
// the total is scw_pkg::ResultWordBits, static_asserted against kPayloadBits (sim/builds/).
#pragma once

#include <cstdint>
#include <tuple>

#include "hls/warning/warning_params.hpp"
#include "scw_pkg.hpp"
#include "sim/words/fields.hpp"
#include "sim/words/pack.hpp"

namespace scw::sim::warning_word {

using hls::warning::FrameResult;
using hls::warning::Severity;
using words::Field;

/// The payload, least significant first. distance_mm is two's complement.
inline constexpr int kCount = pkg::CountBits;
inline constexpr int kCoord = pkg::CoordBits;
inline constexpr auto kResultFields = std::make_tuple(
    Field<FrameResult, Severity>{"severity", pkg::SeverityBits, &FrameResult::severity},
    Field<FrameResult, bool>{"in_tunnel", 1, &FrameResult::in_tunnel},
    Field<FrameResult, bool>{"too_close", 1, &FrameResult::too_close},
    Field<FrameResult, bool>{"tile_overflow", 1, &FrameResult::tile_overflow},
    Field<FrameResult, bool>{"object_overflow", 1, &FrameResult::object_overflow},
    Field<FrameResult, bool>{"stream_error", 1, &FrameResult::stream_error},
    Field<FrameResult, std::uint16_t>{"objects", kCount, &FrameResult::objects},
    Field<FrameResult, std::uint16_t>{"obstacles", kCount, &FrameResult::obstacles},
    Field<FrameResult, std::uint16_t>{"index", kCount, &FrameResult::index},
    Field<FrameResult, std::int32_t>{"distance_mm", pkg::DistMmBits, &FrameResult::distance_mm},
    Field<FrameResult, std::uint16_t>{"closest_x", kCoord, &FrameResult::closest_x},
    Field<FrameResult, std::uint16_t>{"closest_y", kCoord, &FrameResult::closest_y},
    Field<FrameResult, std::uint16_t>{"d_max", kCoord, &FrameResult::d_max},
    Field<FrameResult, std::uint16_t>{"x_min", kCoord, &FrameResult::x_min},
    Field<FrameResult, std::uint16_t>{"x_max", kCoord, &FrameResult::x_max},
    Field<FrameResult, std::uint16_t>{"y_min", kCoord, &FrameResult::y_min},
    Field<FrameResult, std::uint16_t>{"y_max", kCoord, &FrameResult::y_max});

inline constexpr int kPayloadBits = words::bits_of(kResultFields);
static_assert(words::fits_types(kResultFields), "each field fits its C++ member");

}  // namespace scw::sim::warning_word

namespace scw::sim {

template <>
struct BeatLayout<hls::Packet<hls::warning::FrameResult>> {
  using beat_t = hls::Packet<hls::warning::FrameResult>;
  static constexpr int kPayloadBits = warning_word::kPayloadBits;
  static constexpr int kBits = kPayloadBits + 1;

  static Bits payload(const beat_t& b) {
    Bits w(kPayloadBits);
    words::pack_fields(w, 0, b.data, warning_word::kResultFields);
    return w;
  }
  static beat_t from_payload(const Bits& w, bool last) {
    beat_t b;
    b.last = last;
    words::unpack_fields(w, 0, b.data, warning_word::kResultFields);
    return b;
  }
};

}  // namespace scw::sim
