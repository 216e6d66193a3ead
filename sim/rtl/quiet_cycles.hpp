// SPDX-License-Identifier: Apache-2.0
// Skipping the clock cycles of a Verilated model that cannot tell: an idle stage whose state
// only cycles (a ring's pointer going round, pipeline registers holding the last word) while no
// beat comes. Used by the harness (sim/rtl/verilated_harness.hpp, Harness::settle).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <utility>
#include <vector>

namespace scw::sim {

/// What an adapter drove and read in a cycle, for QuietCycles. It drives `key`: its valid and
/// ready bits (QuietKey::bits). A beat's data is written only with valid and, while it is not
/// taken, stays the same beat (a FIFO's head changes only when popped), so with no beat moving the
/// bits fix every input. It reads `out`: kBusy when a beat moved (an input beat taken, or an output
/// beat pushed), else the model's ready and valid outputs as bits.
struct QuietKey {
  static constexpr std::uint32_t kBusy = ~std::uint32_t{0};
  /// The flags as bits, the first one highest.
  template <typename... Bool>
  static std::uint32_t bits(Bool... flags) {
    std::uint32_t k = 0;
    ((k = (k << 1) | static_cast<std::uint32_t>(static_cast<bool>(flags))), ...);
    return k;
  }
};

/// A model is a deterministic function of its state and its inputs, and Verilator keeps the whole
/// state, input ports included, in one object (the symbol table). So when, under unchanged
/// inputs, the state after settling in cycle t + k is byte for byte the one of cycle t, the model
/// runs a loop of k cycles for as long as the inputs stay: its cycles need not be evaluated. When
/// the inputs change, the state of the cycle the loop had reached is rebuilt: the state of cycle
/// t copied back and stepped to the phase, the new input bytes put in again, and the model goes
/// on exactly as if it had been clocked throughout. Results and cycle counts do not change.
///
/// Only a loop in which no beat moves and the ready and valid outputs hold is skipped: a beat's
/// data is read only when it moves, so the skipped cycles read the same as the loop's first.
///
/// The watch for a loop starts after 8 quiet cycles (the same key and outputs, no beat moving),
/// then compares every cycle for up to 4,096 cycles; when no loop is found, the next watch waits
/// twice as long as the last (up to 4,096 quiet cycles), so a model that is never still pays
/// rarely.
class QuietCycles {
 public:
  QuietCycles(unsigned char* state, std::size_t bytes) : state_(state), bytes_(bytes) {}

  bool frozen() const { return frozen_; }
  std::uint64_t skipped() const { return skipped_; }
  /// Forgets loops and watches (the model was reset or driven outside settle).
  void forget() {
    frozen_ = watching_ = false;
    quiet_ = 0;
  }

  /// Before the model settles in a cycle with inputs `key` (written into its state already).
  /// True: the cycle is skipped, its settling and its clock edge. When a loop ends here, the
  /// model is first stepped to where the loop had reached: `edge()` must give it one rising clock
  /// edge, `settle()` settle it (both without tracing or counting). kBusy, which no loop has,
  /// only ends a loop; called so after a clock edge and before the next settle.
  template <typename Edge, typename Settle>
  bool skip(std::uint32_t key, Edge&& edge, Settle&& settle) {
    if (!frozen_) return false;
    if (key == frozen_key_) {
      phase_ = phase_ + 1 == period_ ? 0 : phase_ + 1;
      ++skipped_;
      return true;
    }
    // The bytes the adapter changed are its new inputs: keep them, step the loop's first state
    // to the phase and through the clock edge of the cycle before this one, then put them back.
    std::vector<std::pair<std::size_t, unsigned char>> inputs;
    for (std::size_t i = 0; i < bytes_; ++i)
      if (state_[i] != anchor_[i]) inputs.emplace_back(i, state_[i]);
    std::memcpy(state_, anchor_.data(), bytes_);
    for (std::uint64_t j = 0; j < phase_; ++j) {
      edge();
      settle();
    }
    edge();
    for (const auto& [i, v] : inputs) state_[i] = v;
    frozen_ = false;
    quiet_ = 0;
    return false;
  }

  /// After the model settled in a cycle with inputs `key` and outputs `out` (QuietKey).
  void settled(std::uint32_t key, std::uint32_t out) {
    const bool same = key == last_key_ && out != QuietKey::kBusy && out == last_out_;
    last_key_ = key;
    last_out_ = out;
    if (!same) {
      quiet_ = 0;
      watching_ = false;
      return;
    }
    ++quiet_;
    if (!watching_) {
      if (quiet_ >= next_watch_) {
        anchor_.assign(state_, state_ + bytes_);
        watching_ = true;
        since_ = 0;
      }
      return;
    }
    ++since_;
    if (std::memcmp(anchor_.data(), state_, bytes_) == 0) {
      frozen_ = true;
      watching_ = false;
      frozen_key_ = key;
      period_ = since_;
      phase_ = 0;
      wait_ = kFirstWatch;
      next_watch_ = kFirstWatch;
    } else if (since_ >= kLongestLoop) {
      watching_ = false;
      wait_ = std::min(2 * wait_, kLongestWait);
      next_watch_ = quiet_ + wait_;
    }
  }

 private:
  static constexpr std::uint64_t kFirstWatch = 8;
  static constexpr std::uint64_t kLongestLoop = 4096;
  static constexpr std::uint64_t kLongestWait = 4096;

  unsigned char* state_;
  std::size_t bytes_;
  std::vector<unsigned char> anchor_;  // the state of the loop's (or the watch's) first cycle
  std::uint32_t last_key_ = QuietKey::kBusy;
  std::uint32_t last_out_ = QuietKey::kBusy;
  std::uint32_t frozen_key_ = 0;
  std::uint64_t quiet_ = 0;  // cycles in a row with last_key_
  std::uint64_t next_watch_ = kFirstWatch;
  std::uint64_t wait_ = kFirstWatch;
  std::uint64_t since_ = 0;  // cycles since the anchor
  std::uint64_t period_ = 1;
  std::uint64_t phase_ = 0;  // cycles into the loop
  std::uint64_t skipped_ = 0;
  bool watching_ = false;
  bool frozen_ = false;
};

}  // namespace scw::sim
