// SPDX-License-Identifier: Apache-2.0
// A word's fields listed once, as a table: each field's name (in vectors and CSV), its width,
// and the C++ member that holds it. Packing, unpacking, the vector sets' layout JSON and their
// CSV columns all walk the same table (sim/words/labelling_pack.hpp, warning_pack.hpp).
#pragma once

#include <cstdint>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include "sim/words/bits.hpp"

namespace scw::sim::words {

/// One field of a word, held in the member `member` of S. A signed member is two's complement in
/// the word (sign-extended when read back) unless `Signed` says otherwise (a signed C++ member
/// whose values are never negative); an enum is its underlying code.
template <typename S, typename T, bool Signed = std::is_signed_v<T> && !std::is_same_v<T, bool>>
struct Field {
  using value_type = T;
  const char* name;
  int bits;
  T S::*member;
  static constexpr bool kSigned = Signed;
  static constexpr int kTypeBits = std::is_same_v<T, bool> ? 1 : static_cast<int>(8 * sizeof(T));
  constexpr const T& get(const S& s) const { return s.*member; }
  constexpr T& ref(S& s) const { return s.*member; }
};

/// A field held in a member of a member: `(s.*outer).*member` (e.g. RoadConfig::nominal's a).
template <typename S, typename M, typename T,
          bool Signed = std::is_signed_v<T> && !std::is_same_v<T, bool>>
struct SubField {
  using value_type = T;
  const char* name;
  int bits;
  M S::*outer;
  T M::*member;
  static constexpr bool kSigned = Signed;
  static constexpr int kTypeBits = std::is_same_v<T, bool> ? 1 : static_cast<int>(8 * sizeof(T));
  constexpr const T& get(const S& s) const { return (s.*outer).*member; }
  constexpr T& ref(S& s) const { return (s.*outer).*member; }
};

/// Calls f(field) for each field of a table, in order.
template <typename Table, typename F>
constexpr void for_each(const Table& t, F&& f) {
  std::apply([&](const auto&... x) { (f(x), ...); }, t);
}

template <typename Table>
constexpr int bits_of(const Table& t) {
  int n = 0;
  for_each(t, [&](const auto& x) { n += x.bits; });
  return n;
}

/// Every field's width fits the C++ member that holds it.
template <typename Table>
constexpr bool fits_types(const Table& t) {
  bool ok = true;
  for_each(t, [&](const auto& x) { ok = ok && x.bits >= 1 && x.bits <= x.kTypeBits; });
  return ok;
}

/// CSV columns: `first` (a row's place), then the table's field names.
template <typename Table>
std::vector<std::string> column_names(std::vector<std::string> first, const Table& t) {
  for_each(t, [&](const auto& f) { first.emplace_back(f.name); });
  return first;
}

/// Writes s's fields into w from bit `at` up; returns the bit after the last.
template <typename Table, typename S>
int pack_fields(Bits& w, int at, const S& s, const Table& t) {
  for_each(t, [&](const auto& f) {
    w.set(at, f.bits, static_cast<std::uint64_t>(f.get(s)));
    at += f.bits;
  });
  return at;
}

/// Reads s's fields from w from bit `at` up; returns the bit after the last.
template <typename Table, typename S>
int unpack_fields(const Bits& w, int at, S& s, const Table& t) {
  for_each(t, [&](const auto& f) {
    using F = std::remove_cv_t<std::remove_reference_t<decltype(f)>>;
    using T = typename F::value_type;
    std::uint64_t v = w.get(at, f.bits);
    if constexpr (F::kSigned) {
      if (f.bits < 64 && ((v >> (f.bits - 1)) & 1u)) v |= ~std::uint64_t{0} << f.bits;
    }
    f.ref(s) = static_cast<T>(v);
    at += f.bits;
  });
  return at;
}

/// A whole word of s's fields: the table's width, its first field at bit 0.
template <typename Table, typename S>
Bits pack_word(const S& s, const Table& t) {
  Bits w(bits_of(t));
  pack_fields(w, 0, s, t);
  return w;
}

/// The S a whole word holds (members the table does not list value-initialised).
template <typename S, typename Table>
S unpack_word(const Bits& w, const Table& t) {
  S s{};
  unpack_fields(w, 0, s, t);
  return s;
}

}  // namespace scw::sim::words
