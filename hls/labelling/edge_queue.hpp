// SPDX-License-Identifier: Apache-2.0
// The labelling stage's queue of node pairs to join: up to two pushes and one pop per clock.
#pragma once

#include <array>

namespace scw::hls::labelling {

/// Two nodes found to be one object.
struct Edge {
  int a = 0, b = 0;
  friend bool operator==(const Edge& p, const Edge& q) { return p.a == q.a && p.b == q.b; }
};

/// A register FIFO of `Depth` edges. The pixel decision may push two edges in one clock (a tile
/// corner joins across two borders), the merge unit pops one; `count()` is the registered
/// occupancy every decision of a clock looks at.
template <int Depth>
class EdgeQueue {
 public:
  static constexpr int kDepth = Depth;
  int count() const { return count_; }
  const Edge& head() const { return slots_[head_]; }

  /// One clock: pop the head (if `pop`), then append pushes[0 .. n-1].
  void clock(bool pop, const Edge* pushes, int n) {
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
  std::array<Edge, Depth> slots_{};
  int head_ = 0, count_ = 0;
};

}  // namespace scw::hls::labelling
