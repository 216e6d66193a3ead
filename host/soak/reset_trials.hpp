// SPDX-License-Identifier: Apache-2.0
// Reset in mid-frame: the small build's Verilated scw_pipeline reset at a random cycle while
// frames stream (and Emit, Resolve and the rest run), then fed the next whole frame, against
// the C++ chain: before the reset the two agree clock for clock, after it the top must behave as
// a freshly built C++ chain, and its first frames equal the floating-point reference.
#pragma once

#include <cstdint>
#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "host/soak/soak.hpp"

namespace scw::host::soak {

/// The clocks rst_ni must be held low: one. (It was two until the trials traced a clock lost
/// after a one-clock reset to the labelling stage's phase flags: docs/soak.md, "Reset".)
inline constexpr int kMinResetHold = 1;

struct ResetOptions {
  int trials = 200;
  std::uint64_t seed = 1;
  int width = 64, height = 32;
  bool stalls = true;  // random input gaps and output backpressure
  RealPair real;
  Progress progress;

  /// `trials` resets on the soak's frame size, seed, stalls, real pair and progress.
  /// Named assignments, not an aggregate in field order: two int fields swapped would still
  /// compile.
  static ResetOptions like(const SoakOptions& soak, int trials) {
    ResetOptions r;
    r.trials = trials;
    r.seed = soak.seed;
    r.width = soak.width;
    r.height = soak.height;
    r.stalls = soak.stalls;
    r.real = soak.real;
    r.progress = soak.progress;
    return r;
  }
};

struct ResetSummary {
  int trials = 0;
  int failures = 0;  // trials with any of the three below, or stuck
  int before_mismatches = 0;     // results before the reset: top != C++ chain
  int after_mismatches = 0;      // results after it: top != a fresh C++ chain
  int reference_mismatches = 0;  // the first two frames after it != the reference chain
  int reference_boundary = 0;    // ... differing only at a decision boundary: not failures
  std::map<std::string, int> busy;       // block -> resets in the 8 cycles after it moved a beat
  std::map<std::string, int> labelling;  // the labelling stage's phase at the reset
  std::string first_failure;
  nlohmann::json to_json() const;
};

/// Trial t: frames of soak content (seed and t), the top reset at a cycle drawn from the first
/// three frames' span among those where the labelling stage is in the t-th of its activities,
/// held in reset kMinResetHold .. 8 cycles. Throws std::invalid_argument for a frame size the
/// small build cannot take.
ResetSummary run_reset_trials(const ResetOptions& o);

}  // namespace scw::host::soak
