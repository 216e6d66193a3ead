// SPDX-License-Identifier: Apache-2.0
// The labelling stage's output word, {last, payload}: what the RTL's out_data_o carries and the
// golden vectors store. Its fields are listed once, in kObjectFields and kStatusFields, with
// the widths of rtl_models/common/scw_pkg.sv (scw_pkg.hpp is generated from it): packing,
// unpacking, the vector sets' layout JSON and their CSV columns all walk these tables.
#pragma once

#include <cstdint>
#include <tuple>

#include "hls/labelling/labelling_params.hpp"
#include "scw_pkg.hpp"
#include "sim/words/fields.hpp"
#include "sim/words/pack.hpp"

namespace scw::sim::labelling_word {

using hls::labelling::FrameStatus;
using hls::labelling::Object;

using words::Field;

/// An object word after its is_status bit, least significant first: scw_pkg's label_desc_t
/// read from its last member up.
inline constexpr auto kObjectFields = std::make_tuple(
    Field<Object, std::uint32_t>{"area", pkg::AreaBits, &Object::area},
    Field<Object, std::uint16_t>{"x_min", pkg::CoordBits, &Object::x_min},
    Field<Object, std::uint16_t>{"x_max", pkg::CoordBits, &Object::x_max},
    Field<Object, std::uint16_t>{"y_min", pkg::CoordBits, &Object::y_min},
    Field<Object, std::uint16_t>{"y_max", pkg::CoordBits, &Object::y_max},
    Field<Object, std::uint16_t>{"d_min", pkg::CoordBits, &Object::d_min},
    Field<Object, std::uint16_t>{"d_max", pkg::CoordBits, &Object::d_max},
    Field<Object, std::uint16_t>{"closest_x", pkg::CoordBits, &Object::closest_x},
    Field<Object, std::uint16_t>{"closest_y", pkg::CoordBits, &Object::closest_y},
    Field<Object, std::uint16_t>{"first_x", pkg::CoordBits, &Object::first_x},
    Field<Object, std::uint16_t>{"first_y", pkg::CoordBits, &Object::first_y},
    Field<Object, std::uint64_t>{"m10", pkg::SumBits, &Object::m10},
    Field<Object, std::uint64_t>{"m01", pkg::SumBits, &Object::m01},
    Field<Object, std::uint64_t>{"m20", pkg::SumBits, &Object::m20},
    Field<Object, std::uint64_t>{"m11", pkg::SumBits, &Object::m11},
    Field<Object, std::uint64_t>{"m02", pkg::SumBits, &Object::m02},
    Field<Object, std::uint64_t>{"m30", pkg::SumBits, &Object::m30},
    Field<Object, std::uint64_t>{"m21", pkg::SumBits, &Object::m21},
    Field<Object, std::uint64_t>{"m12", pkg::SumBits, &Object::m12},
    Field<Object, std::uint64_t>{"m03", pkg::SumBits, &Object::m03},
    Field<Object, std::uint64_t>{"sum_d", pkg::SumBits, &Object::sum_d},
    Field<Object, std::uint64_t>{"sum_dd", pkg::SumBits, &Object::sum_dd});

/// A status word after its is_status bit: the object count in the area field's place, the
/// flags just above it (scw_pkg's label_status_t).
inline constexpr auto kStatusFields = std::make_tuple(
    Field<FrameStatus, std::uint32_t>{"objects", pkg::AreaBits, &FrameStatus::objects},
    Field<FrameStatus, bool>{"tile_overflow", 1, &FrameStatus::tile_overflow},
    Field<FrameStatus, bool>{"object_overflow", 1, &FrameStatus::object_overflow},
    Field<FrameStatus, bool>{"stream_error", 1, &FrameStatus::stream_error});

inline constexpr int kPayloadBits = 1 + words::bits_of(kObjectFields);
static_assert(1 + words::bits_of(kStatusFields) <= kPayloadBits,
              "a status word fits an object word");
static_assert(words::fits_types(kObjectFields) && words::fits_types(kStatusFields),
              "scw_pkg.sv's widths fit the C++ fields (hls/labelling/labelling_params.hpp)");

}  // namespace scw::sim::labelling_word

namespace scw::sim {

template <>
struct BeatLayout<hls::Packet<hls::labelling::LabelWord>> {
  using beat_t = hls::Packet<hls::labelling::LabelWord>;
  static constexpr int kPayloadBits = labelling_word::kPayloadBits;
  static constexpr int kBits = kPayloadBits + 1;

  static Bits payload(const beat_t& b) {
    Bits w(kPayloadBits);
    const auto& d = b.data;
    w.set(0, 1, d.is_status);
    if (d.is_status)
      words::pack_fields(w, 1, d.status, labelling_word::kStatusFields);
    else
      words::pack_fields(w, 1, d.object, labelling_word::kObjectFields);
    return w;
  }
  static beat_t from_payload(const Bits& w, bool last) {
    beat_t b;
    b.last = last;
    auto& d = b.data;
    d.is_status = w.get(0, 1) != 0;
    if (d.is_status)
      words::unpack_fields(w, 1, d.status, labelling_word::kStatusFields);
    else
      words::unpack_fields(w, 1, d.object, labelling_word::kObjectFields);
    return b;
  }
};

}  // namespace scw::sim
