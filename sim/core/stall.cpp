// SPDX-License-Identifier: Apache-2.0
// Stall patterns: names, parsing, and the per-cycle generators.
#include "sim/core/stall.hpp"

#include <stdexcept>

namespace scw::sim {

std::string StallPattern::name() const {
  switch (kind) {
    case StallKind::kNone: return "none";
    case StallKind::kIdleInput: return "idle";
    case StallKind::kBackpressure: return "backpressure";
    case StallKind::kBoth: return "both";
    case StallKind::kRandom: return "random:" + std::to_string(seed);
  }
  return "?";
}

std::vector<StallPattern> StallPattern::all(int random_seeds) {
  std::vector<StallPattern> v = {{StallKind::kNone, 0},
                                 {StallKind::kIdleInput, 0},
                                 {StallKind::kBackpressure, 0},
                                 {StallKind::kBoth, 0}};
  for (int s = 1; s <= random_seeds; ++s)
    v.push_back({StallKind::kRandom, 0x5c3a11u * static_cast<std::uint64_t>(s)});
  return v;
}

StallPattern StallPattern::parse(const std::string& text) {
  if (text == "none") return {StallKind::kNone, 0};
  if (text == "idle") return {StallKind::kIdleInput, 0};
  if (text == "backpressure") return {StallKind::kBackpressure, 0};
  if (text == "both") return {StallKind::kBoth, 0};
  const std::string prefix = "random:";
  if (text.rfind(prefix, 0) == 0) {
    try {
      std::size_t used = 0;
      const auto seed = std::stoull(text.substr(prefix.size()), &used);
      if (used == text.size() - prefix.size()) return {StallKind::kRandom, seed};
    } catch (const std::exception&) {
    }
  }
  throw std::invalid_argument("unknown stall pattern '" + text +
                              "': use none, idle, backpressure, both or random:<seed>");
}

StallGen::StallGen(const StallPattern& p, Side side)
    : active_(side == Side::kInput ? p.stalls_input() : p.stalls_output()),
      random_(p.kind == StallKind::kRandom),
      side_(side),
      // Different streams for the two sides, so random input gaps and backpressure are
      // independent of each other.
      rng_(p.seed * 2 + (side == Side::kInput ? 0 : 1)) {}

bool StallGen::next() {
  const std::uint64_t n = n_++;
  if (!active_) return true;
  if (random_) {
    // Input offers 70 % of cycles, output accepts 60 %: sustained stalls on both sides.
    const std::uint64_t r = rng_() % 100;
    return side_ == Side::kInput ? r < 70 : r < 60;
  }
  // Input: 1,1,1,0 (period 4). Output: 1,1,0,1,0,0,1 (period 7), co-prime with the input.
  static constexpr bool kIn[] = {true, true, true, false};
  static constexpr bool kOut[] = {true, true, false, true, false, false, true};
  return side_ == Side::kInput ? kIn[n % 4] : kOut[n % 7];
}

}  // namespace scw::sim
