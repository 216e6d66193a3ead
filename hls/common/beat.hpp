// SPDX-License-Identifier: Apache-2.0
// The stream beat shared by every stage: P pixels of one row with AXI4-Stream video flags.
#pragma once

#include <array>
#include <cstdint>
#include <type_traits>
#include <utility>

namespace scw::hls {

using pixel_t = std::uint8_t;  // Q8.0 grey level

/// One transfer on a pixel stream: `P` consecutive pixels of one row.
/// `sof` (AXI TUSER[0]) marks the first beat of a frame, `eol` (TLAST) the last beat of a row.
/// Pixel 0 is the leftmost and sits in the least significant bits of the packed RTL word.
template <typename T, int P>
struct Beat {
  static_assert(P == 1 || P == 2 || P == 4, "P (pixels per beat) must be 1, 2 or 4");
  static constexpr int kPixels = P;
  using value_type = T;

  std::array<T, P> px{};
  bool sof = false;
  bool eol = false;

  friend bool operator==(const Beat& a, const Beat& b) {
    return a.px == b.px && a.sof == b.sof && a.eol == b.eol;
  }
  friend bool operator!=(const Beat& a, const Beat& b) { return !(a == b); }
};

/// One transfer on a non-image stream (object tables, frame results): `last` ends a frame's
/// burst.
template <typename T>
struct Packet {
  T data{};
  bool last = false;

  friend bool operator==(const Packet& a, const Packet& b) {
    return a.data == b.data && a.last == b.last;
  }
  friend bool operator!=(const Packet& a, const Packet& b) { return !(a == b); }
};

namespace detail {
template <typename B, typename = void>
struct has_sof : std::false_type {};
template <typename B>
struct has_sof<B, std::void_t<decltype(std::declval<const B&>().sof)>> : std::true_type {};
template <typename B, typename = void>
struct has_last : std::false_type {};
template <typename B>
struct has_last<B, std::void_t<decltype(std::declval<const B&>().last)>> : std::true_type {};
}  // namespace detail

/// Frame boundaries, so that sim/ can time-stamp any stream without knowing its geometry:
/// pixel streams start a frame at `sof`; packet streams start one after a `last`; other
/// types carry no frames.
template <typename B>
constexpr bool starts_frame(const B& b, bool after_last) {
  if constexpr (detail::has_sof<B>::value) {
    return b.sof;
  } else if constexpr (detail::has_last<B>::value) {
    return after_last;
  } else {
    return false;
  }
}
template <typename B>
constexpr bool ends_burst(const B& b) {
  if constexpr (detail::has_last<B>::value) {
    return b.last;
  } else {
    return false;
  }
}

}  // namespace scw::hls
