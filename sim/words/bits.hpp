// SPDX-License-Identifier: Apache-2.0
// A packed bit vector of any width: the RTL word of a beat, a Verilator port, a hex line.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <algorithm>
#include <string_view>
#include <vector>

namespace scw::sim {

/// Packed bits, bit 0 = least significant, the layout Verilator and $readmemh use.
class Bits {
 public:
  Bits() = default;
  explicit Bits(int width) : width_(width), words_(static_cast<std::size_t>((width + 31) / 32)) {}

  int width() const { return width_; }

  /// Writes `n` (<= 64) bits of `value` at bit `lsb`.
  void set(int lsb, int n, std::uint64_t value) {
    check_range(lsb, n);
    for (int i = 0; i < n; ++i) {
      const int b = lsb + i;
      const std::uint32_t mask = 1u << (b % 32);
      auto& w = words_[static_cast<std::size_t>(b / 32)];
      w = ((value >> i) & 1u) ? (w | mask) : (w & ~mask);
    }
  }
  /// Reads `n` (<= 64) bits at bit `lsb`.
  std::uint64_t get(int lsb, int n) const {
    check_range(lsb, n);
    std::uint64_t v = 0;
    for (int i = 0; i < n; ++i) {
      const int b = lsb + i;
      v |= static_cast<std::uint64_t>((words_[static_cast<std::size_t>(b / 32)] >> (b % 32)) & 1u)
           << i;
    }
    return v;
  }
  std::uint32_t word(std::size_t i) const { return words_.at(i); }
  std::size_t num_words() const { return words_.size(); }

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
    return a.width_ == b.width_ && a.words_ == b.words_;
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
      for (std::size_t i = 0; i < n; ++i) port.m_storage[i] = i < words_.size() ? words_[i] : 0;
    }
  }
  template <typename Port>
  static Bits from_port(const Port& port, int width) {
    Bits b(width);
    if constexpr (std::is_integral_v<Port>) {
      b.set(0, std::min(width, 64), static_cast<std::uint64_t>(port));
    } else {
      constexpr std::size_t n = sizeof(port.m_storage) / sizeof(port.m_storage[0]);
      for (std::size_t i = 0; i < b.words_.size() && i < n; ++i) b.words_[i] = port.m_storage[i];
      b.mask_top();
    }
    return b;
  }

 private:
  void check_range(int lsb, int n) const {
    if (lsb < 0 || n < 0 || n > 64 || lsb + n > width_)
      throw std::out_of_range("bit field [" + std::to_string(lsb) + " +: " + std::to_string(n) +
                              "] outside a " + std::to_string(width_) + "-bit word");
  }
  void mask_top() {
    if (width_ % 32 != 0 && !words_.empty()) words_.back() &= (1u << (width_ % 32)) - 1u;
  }

  int width_ = 0;
  std::vector<std::uint32_t> words_;
};

}  // namespace scw::sim
