// SPDX-License-Identifier: Apache-2.0
// The labelling stage's merge unit: joins the nodes of each queued edge in the parent RAM.
#pragma once

#include "hls/labelling/edge_queue.hpp"

namespace scw::hls::labelling {

/// The parent RAM's ports for one clock: one registered read, one write.
struct ParentPorts {
  bool rd = false;
  int rd_addr = 0;
  bool wr = false;
  int wr_addr = 0;
  int wr_data = 0;
};

/// Union-find over the parent RAM, one edge at a time (docs/labelling.md "Merge unit").
/// parent[n] = 0: n is a root; else parent[n] - 1 < n. Roots link larger under smaller, so a
/// component's root is its smallest node. States and clocks:
///   kIdle   pop an edge (a, b), read parent[a]
///   kFindA  follow parent[] from a, one read per clock, to its root ra; then read parent[b]
///   kFindB  follow parent[] from b to rb; in the clock it is found write parent[max] = min + 1
///           when ra != rb
///   kPathA  write parent[a] = root + 1 unless a is the root (path compression)
///   kPathB  the same for b, then kIdle
/// An edge takes depth(a) + depth(b) + 5 clocks.
class UnionFind {
 public:
  enum State { kIdle, kFindA, kFindB, kPathA, kPathB };

  bool idle() const { return state_ == kIdle; }

  /// One clock. `rd_data` = parent[] at the address read in the previous clock. Returns whether
  /// the queue's head is popped; fills `ports`.
  template <int Depth>
  bool clock(const EdgeQueue<Depth>& q, int rd_data, ParentPorts& ports) {
    bool pop = false;
    switch (state_) {
      case kIdle:
        if (q.count() > 0) {
          pop = true;
          a_ = q.head().a;
          b_ = q.head().b;
          read(ports, a_);
          state_ = kFindA;
        }
        break;
      case kFindA:
        if (rd_data == 0) {
          ra_ = cur_;
          read(ports, b_);
          state_ = kFindB;
        } else {
          read(ports, rd_data - 1);
        }
        break;
      case kFindB:
        if (rd_data == 0) {
          const int rb = cur_;
          root_ = ra_ < rb ? ra_ : rb;
          if (ra_ != rb) write(ports, ra_ < rb ? rb : ra_, root_ + 1);
          state_ = kPathA;
        } else {
          read(ports, rd_data - 1);
        }
        break;
      case kPathA:
        if (a_ != root_) write(ports, a_, root_ + 1);
        state_ = kPathB;
        break;
      case kPathB:
        if (b_ != root_) write(ports, b_, root_ + 1);
        state_ = kIdle;
        break;
    }
    return pop;
  }

 private:
  void read(ParentPorts& p, int addr) {
    p.rd = true;
    p.rd_addr = addr;
    cur_ = addr;
  }
  static void write(ParentPorts& p, int addr, int data) {
    p.wr = true;
    p.wr_addr = addr;
    p.wr_data = data;
  }

  State state_ = kIdle;
  int a_ = 0, b_ = 0, ra_ = 0, root_ = 0;
  int cur_ = 0;  // the node whose parent[] is being read
};

}  // namespace scw::hls::labelling
