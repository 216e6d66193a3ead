// SPDX-License-Identifier: Apache-2.0
// Stall patterns for stream drivers and sinks: none, idle input, backpressure, both, random.
#pragma once

#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace scw::sim {

/// Which side stalls. `kRandom` stalls both sides from a seeded generator.
enum class StallKind { kNone, kIdleInput, kBackpressure, kBoth, kRandom };

struct StallPattern {
  StallKind kind = StallKind::kNone;
  std::uint64_t seed = 0;  // used by kRandom only

  bool stalls_input() const { return kind != StallKind::kNone && kind != StallKind::kBackpressure; }
  bool stalls_output() const { return kind != StallKind::kNone && kind != StallKind::kIdleInput; }
  std::string name() const;

  /// The four fixed patterns plus `random_seeds` seeded random ones: what every RTL test runs.
  static std::vector<StallPattern> all(int random_seeds = 3);
  /// The same pattern for a second stream at the same end (the right camera, the object
  /// table), with its own random draws, so the two do not stall in step.
  StallPattern other_stream(std::uint64_t salt) const {
    StallPattern p = *this;
    p.seed = seed * 7919 + salt;
    return p;
  }
  /// Parses "none", "idle", "backpressure", "both" or "random:<seed>".
  static StallPattern parse(const std::string& text);
};

/// Produces the per-cycle decision of one side: may the driver offer a beat, may the sink take
/// one. The fixed patterns are short cycles that do not line up with each other or with P
/// (as verilog-axis's [1,1,1,0] pause), the random one is a seeded Bernoulli draw.
class StallGen {
 public:
  enum class Side { kInput, kOutput };
  StallGen(const StallPattern& p, Side side);
  /// True if this side goes ahead this cycle; advances the pattern by one cycle.
  bool next();

 private:
  bool active_;
  bool random_;
  Side side_;
  std::uint64_t n_ = 0;
  std::mt19937_64 rng_;
};

}  // namespace scw::sim
