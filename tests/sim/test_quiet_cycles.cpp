// SPDX-License-Identifier: Apache-2.0
// QuietCycles, the harness's skipping of still cycles, on a toy machine whose idle loop has a
// phase that shows later: left at any phase, it must go on exactly as the machine clocked
// throughout. (The Verilated warning stage is held to its model the same way in
// tests/warning/test_warning_rtl.cpp.)
#include <array>
#include <catch2/catch.hpp>
#include <cstdint>

#include "sim/rtl/quiet_cycles.hpp"

namespace {

using scw::sim::QuietCycles;
using scw::sim::QuietKey;

/// The state as Verilator keeps it, one object, input port included: `in` (0: no beat), a counter
/// that goes round `period` values while idle, and an accumulator that a beat adds the counter to,
/// so the phase at which an idle stretch ends decides the result.
struct Toy {
  std::array<std::uint8_t, 4> s{};  // in, counter, accumulator, period
  explicit Toy(std::uint8_t period) { s[3] = period; }
  void edge() {
    if (s[0] == 0) {
      s[1] = static_cast<std::uint8_t>((s[1] + 1) % s[3]);
    } else {
      s[2] = static_cast<std::uint8_t>(s[2] + s[1] * s[0]);
      s[1] = 0;
    }
  }
};

/// The input of cycle c: long idle stretches of varying length, then a beat.
std::uint8_t input(int c) {
  const int block = 300 + (c / 1000) * 7;
  return c % block == block - 1 ? static_cast<std::uint8_t>(1 + c % 5) : 0;
}

}  // namespace

TEST_CASE("skipped idle loops end at the right phase, whatever the loop's length", "[sim][rtl]") {
  for (std::uint8_t period : {1, 2, 5, 64}) {
    INFO("idle loop of " << int(period) << " cycles");
    Toy clocked(period), skipping(period);
    QuietCycles q(skipping.s.data(), skipping.s.size());
    for (int c = 0; c < 20000; ++c) {
      clocked.s[0] = skipping.s[0] = input(c);
      const std::uint32_t key = QuietKey::bits(skipping.s[0] != 0);
      // The cycle as the harness runs it: settle (nothing to settle here), then the clock edge.
      if (!q.skip(
              key, [&] { skipping.edge(); }, [] {})) {
        q.settled(key, skipping.s[0] != 0 ? QuietKey::kBusy : 0);
        INFO("cycle " << c);
        REQUIRE(skipping.s == clocked.s);
      }
      if (!q.frozen()) skipping.edge();
      clocked.edge();
    }
    CHECK(q.skipped() > 15000);
  }
}
