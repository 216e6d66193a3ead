// SPDX-License-Identifier: Apache-2.0
// Packing of beats into RTL words: {eol, sof, payload}, the layout FIFOs and hex vectors use.
#pragma once

#include <cstdint>
#include <type_traits>
#include <vector>

#include "hls/common/beat.hpp"
#include "hls/common/line_buffer.hpp"
#include "hls/rectify/rectify_params.hpp"
#include "sim/words/bits.hpp"

namespace scw::sim {

template <typename T>
constexpr int value_bits() {
  static_assert(std::is_unsigned_v<T>, "pixels are unsigned integers");
  return static_cast<int>(sizeof(T) * 8);
}

/// Width and packing of a beat's payload (pixels) and of the whole word with its flags.
template <typename B>
struct BeatLayout;

template <typename T, int P>
struct BeatLayout<hls::Beat<T, P>> {
  using beat_t = hls::Beat<T, P>;
  static constexpr int kPayloadBits = P * value_bits<T>();
  static constexpr int kBits = kPayloadBits + 2;

  static Bits payload(const beat_t& b) {
    Bits w(kPayloadBits);
    for (int i = 0; i < P; ++i) w.set(i * value_bits<T>(), value_bits<T>(), b.px[i]);
    return w;
  }
  static beat_t from_payload(const Bits& w, bool sof, bool eol) {
    beat_t b;
    for (int i = 0; i < P; ++i) b.px[i] = static_cast<T>(w.get(i * value_bits<T>(), value_bits<T>()));
    b.sof = sof;
    b.eol = eol;
    return b;
  }
  static bool sof(const beat_t& b) { return b.sof; }
  static bool eol(const beat_t& b) { return b.eol; }
};

template <typename T, int P, int Rows>
struct BeatLayout<hls::ColumnBeat<T, P, Rows>> {
  using beat_t = hls::ColumnBeat<T, P, Rows>;
  static constexpr int kRowBits = P * value_bits<T>();
  static constexpr int kPayloadBits = Rows * kRowBits;
  static constexpr int kBits = kPayloadBits + 2;

  static Bits payload(const beat_t& b) {
    Bits w(kPayloadBits);
    for (int k = 0; k < Rows; ++k)
      for (int i = 0; i < P; ++i)
        w.set(k * kRowBits + i * value_bits<T>(), value_bits<T>(), b.rows[k][i]);
    return w;
  }
  static beat_t from_payload(const Bits& w, bool sof, bool eol) {
    beat_t b;
    for (int k = 0; k < Rows; ++k)
      for (int i = 0; i < P; ++i)
        b.rows[k][i] =
            static_cast<T>(w.get(k * kRowBits + i * value_bits<T>(), value_bits<T>()));
    b.sof = sof;
    b.eol = eol;
    return b;
  }
  static bool sof(const beat_t& b) { return b.sof; }
  static bool eol(const beat_t& b) { return b.eol; }
};

/// Map beats: per pixel {y, x}, each a CoordBits-bit two's-complement number, pixel 0 lowest.
template <int P, int CB>
struct BeatLayout<hls::rectify::MapBeat<P, CB>> {
  using beat_t = hls::rectify::MapBeat<P, CB>;
  static constexpr int kPointBits = 2 * CB;
  static constexpr int kPayloadBits = P * kPointBits;
  static constexpr int kBits = kPayloadBits + 2;

  static Bits payload(const beat_t& b) {
    constexpr std::uint64_t mask = (std::uint64_t{1} << CB) - 1;
    Bits w(kPayloadBits);
    for (int i = 0; i < P; ++i) {
      w.set(i * kPointBits, CB, static_cast<std::uint64_t>(b.px[i].x) & mask);
      w.set(i * kPointBits + CB, CB, static_cast<std::uint64_t>(b.px[i].y) & mask);
    }
    return w;
  }
  static beat_t from_payload(const Bits& w, bool sof, bool eol) {
    auto sext = [](std::uint64_t v) {
      return static_cast<std::int32_t>(static_cast<std::int64_t>(v << (64 - CB)) >> (64 - CB));
    };
    beat_t b;
    for (int i = 0; i < P; ++i) {
      b.px[i].x = sext(w.get(i * kPointBits, CB));
      b.px[i].y = sext(w.get(i * kPointBits + CB, CB));
    }
    b.sof = sof;
    b.eol = eol;
    return b;
  }
  static bool sof(const beat_t& b) { return b.sof; }
  static bool eol(const beat_t& b) { return b.eol; }
};

/// The whole word: payload in the low bits, then sof, then eol; a packet's payload, then last.
template <typename B>
Bits pack(const B& b) {
  using L = BeatLayout<B>;
  const Bits p = L::payload(b);
  Bits w(L::kBits);
  for (int lsb = 0; lsb < L::kPayloadBits; lsb += 32) {
    const int n = std::min(32, L::kPayloadBits - lsb);
    w.set(lsb, n, p.get(lsb, n));
  }
  if constexpr (hls::detail::has_last<B>::value) {
    w.set(L::kPayloadBits, 1, b.last);
  } else {
    w.set(L::kPayloadBits, 1, L::sof(b));
    w.set(L::kPayloadBits + 1, 1, L::eol(b));
  }
  return w;
}

/// Every beat of a stream packed (a vector set's hex lines).
template <typename B>
std::vector<Bits> pack_all(const std::vector<B>& beats) {
  std::vector<Bits> v;
  v.reserve(beats.size());
  for (const auto& b : beats) v.push_back(pack(b));
  return v;
}

template <typename B>
B unpack(const Bits& w) {
  using L = BeatLayout<B>;
  Bits p(L::kPayloadBits);
  for (int lsb = 0; lsb < L::kPayloadBits; lsb += 32) {
    const int n = std::min(32, L::kPayloadBits - lsb);
    p.set(lsb, n, w.get(lsb, n));
  }
  if constexpr (hls::detail::has_last<B>::value) {
    return L::from_payload(p, w.get(L::kPayloadBits, 1) != 0);
  } else {
    return L::from_payload(p, w.get(L::kPayloadBits, 1) != 0,
                           w.get(L::kPayloadBits + 1, 1) != 0);
  }
}

}  // namespace scw::sim
