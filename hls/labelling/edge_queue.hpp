// SPDX-License-Identifier: Apache-2.0
// The labelling stage's queue of node pairs to join: several pushes and one pop per clock.
#pragma once

#include "hls/common/reg_fifo.hpp"

namespace scw::hls::labelling {

/// Two nodes found to be one object.
struct Edge {
  int a = 0, b = 0;
  friend bool operator==(const Edge& p, const Edge& q) { return p.a == q.a && p.b == q.b; }
};

/// A register FIFO of `Depth` edges. A lane's pixel decision may push two edges in one clock (a
/// tile corner joins across two borders), the strip-border sweep one per border; the merge unit
/// pops one.
template <int Depth>
using EdgeQueue = RegFifo<Edge, Depth>;

}  // namespace scw::hls::labelling
