// SPDX-License-Identifier: Apache-2.0
// A packed bit vector of any width: the RTL word of a beat, a Verilator port, a hex line.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace scw::sim {

/// Packed bits, bit 0 = least significant, the layout Verilator and $readmemh use.
class Bits {
 public:
  Bits() = default;
  explicit Bits(int width) : width_(width), n_((width + 31) / 32) {
    if (n_ > kInline) big_.assign(static_cast<std::size_t>(n_), 0u);
  }

  int width() const { return width_; }

  /// Writes `n` (<= 64) bits of `value` at bit `lsb`, a 32-bit word at a time (a field spans at
  /// most three): every beat of a Verilated port goes through here each clock.
  void set(int lsb, int n, std::uint64_t value) {
    check_range(lsb, n);
    std::uint32_t* w = data();
    for (int b = lsb, left = n; left > 0;) {
      const int off = b % 32, take = std::min(left, 32 - off);
      const std::uint32_t mask = (take == 32 ? ~0u : (1u << take) - 1u) << off;
      auto& word = w[b / 32];
      word = (word & ~mask) | ((static_cast<std::uint32_t>(value) << off) & mask);
      value >>= take;
      b += take;
      left -= take;
    }
  }
  /// Reads `n` (<= 64) bits at bit `lsb`.
  std::uint64_t get(int lsb, int n) const {
    check_range(lsb, n);
    const std::uint32_t* w = data();
    std::uint64_t v = 0;
    for (int b = lsb, done = 0; done < n;) {
      const int off = b % 32, take = std::min(n - done, 32 - off);
      const std::uint32_t mask = take == 32 ? ~0u : (1u << take) - 1u;
      v |= static_cast<std::uint64_t>((w[b / 32] >> off) & mask) << done;
      b += take;
      done += take;
    }
    return v;
  }
  std::uint32_t word(std::size_t i) const {
    if (i >= static_cast<std::size_t>(n_))
      throw std::out_of_range("word " + std::to_string(i) + " of a " + std::to_string(width_) +
                              "-bit word");
    return data()[i];
  }
  std::size_t num_words() const { return static_cast<std::size_t>(n_); }

  /// Most significant digit first, ceil(width/4) digits: one `$readmemh` line.
  std::string hex() const {
    static constexpr char kDigits[] = "0123456789abcdef";
    const int digits = (width_ + 3) / 4;
    std::string s(static_cast<std::size_t>(digits), '0');
    for (int d = 0; d < digits; ++d) {
      const int n = std::min(4, width_ - 4 * d);
      s[static_cast<std::size_t>(digits - 1 - d)] = kDigits[get(4 * d, n)];
    }
    return s;
  }
  /// Parses a hex line of a `width`-bit word; throws on a bad digit or a value too wide.
  static Bits from_hex(std::string_view text, int width) {
    Bits b(width);
    int bit = 0;
    for (auto it = text.rbegin(); it != text.rend(); ++it, bit += 4) {
      const char c = *it;
      int v;
      if (c >= '0' && c <= '9') v = c - '0';
      else if (c >= 'a' && c <= 'f') v = c - 'a' + 10;
      else if (c >= 'A' && c <= 'F') v = c - 'A' + 10;
      else throw std::invalid_argument("bad hex digit '" + std::string(1, c) + "' in '" +
                                       std::string(text) + "'");
      for (int i = 0; i < 4; ++i) {
        if (!((v >> i) & 1)) continue;
        if (bit + i >= width)
          throw std::invalid_argument("hex value '" + std::string(text) + "' is wider than " +
                                      std::to_string(width) + " bits");
        b.set(bit + i, 1, 1);
      }
    }
    return b;
  }

  friend bool operator==(const Bits& a, const Bits& b) {
    return a.width_ == b.width_ && std::equal(a.data(), a.data() + a.n_, b.data());
  }
  friend bool operator!=(const Bits& a, const Bits& b) { return !(a == b); }

  // ---- Verilator ports: CData/SData/IData/QData, or VlWide<N> (duck-typed: no Verilator
  // header needed here, so host code can use Bits without Verilator) -------------------------
  template <typename Port>
  void to_port(Port& port) const {
    if constexpr (std::is_integral_v<Port>) {
      port = static_cast<Port>(width_ > 0 ? get(0, std::min(width_, 64)) : 0);
    } else {
      constexpr std::size_t n = sizeof(port.m_storage) / sizeof(port.m_storage[0]);
      const std::uint32_t* w = data();
      for (std::size_t i = 0; i < n; ++i)
        port.m_storage[i] = i < static_cast<std::size_t>(n_) ? w[i] : 0;
    }
  }
  template <typename Port>
  static Bits from_port(const Port& port, int width) {
    Bits b(width);
    if constexpr (std::is_integral_v<Port>) {
      b.set(0, std::min(width, 64), static_cast<std::uint64_t>(port));
    } else {
      constexpr std::size_t n = sizeof(port.m_storage) / sizeof(port.m_storage[0]);
      std::uint32_t* w = b.data();
      for (std::size_t i = 0; i < static_cast<std::size_t>(b.n_) && i < n; ++i)
        w[i] = port.m_storage[i];
      b.mask_top();
    }
    return b;
  }

 private:
  // The check inline, the message out of line: every port field of every clock passes here.
  void check_range(int lsb, int n) const {
    if (__builtin_expect(lsb < 0 || n < 0 || n > 64 || lsb + n > width_, 0)) range_error(lsb, n);
  }
  [[noreturn, gnu::noinline, gnu::cold]] void range_error(int lsb, int n) const {
    throw std::out_of_range("bit field [" + std::to_string(lsb) + " +: " + std::to_string(n) +
                            "] outside a " + std::to_string(width_) + "-bit word");
  }
  void mask_top() {
    if (width_ % 32 != 0 && n_ > 0) data()[n_ - 1] &= (1u << (width_ % 32)) - 1u;
  }
  std::uint32_t* data() { return n_ > kInline ? big_.data() : small_.data(); }
  const std::uint32_t* data() const { return n_ > kInline ? big_.data() : small_.data(); }

  // Words up to kInline live in the object, so the beats of every port but the widest (the
  // labelling word) are packed each clock without a heap allocation.
  static constexpr int kInline = 8;
  int width_ = 0;
  int n_ = 0;  // 32-bit words
  std::array<std::uint32_t, kInline> small_{};
  std::vector<std::uint32_t> big_;
};

}  // namespace scw::sim
