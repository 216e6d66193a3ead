// SPDX-License-Identifier: Apache-2.0
// A register FIFO with one pop and several pushes per clock, as the RTL's register FIFOs hold
// it: what a clock pushes is seen from the next clock on.
#pragma once

#include <array>

namespace scw::hls {

/// `Depth` entries of `T`. The caller never pushes into a full FIFO; `count()` is the
/// registered occupancy every decision of a clock looks at.
template <typename T, int Depth>
class RegFifo {
 public:
  static_assert(Depth >= 1, "a FIFO of at least one entry");
  static constexpr int kDepth = Depth;
  int count() const { return count_; }
  bool empty() const { return count_ == 0; }
  bool full() const { return count_ == Depth; }
  const T& head() const { return slots_[head_]; }

  /// One clock: pop the head (if `pop`), then append pushes[0 .. n-1].
  void clock(bool pop, const T* pushes, int n) {
    if (pop) {
      head_ = (head_ + 1) % Depth;
      --count_;
    }
    for (int i = 0; i < n; ++i) {
      slots_[(head_ + count_) % Depth] = pushes[i];
      ++count_;
    }
  }

 private:
  std::array<T, Depth> slots_{};
  int head_ = 0, count_ = 0;
};

}  // namespace scw::hls
