// SPDX-License-Identifier: Apache-2.0
// SystemVerilog's $clog2 at compile time, and the power of two it implies: the widths, tree
// depths and memory depths that the C++ models and the RTL derive from the same parameters.
#pragma once

namespace scw::hls {

/// ceil(log2 v): the bits of an address of v entries, as $clog2(v) (0 for v <= 1).
constexpr int clog2(long long v) {
  int b = 0;
  while ((1LL << b) < v) ++b;
  return b;
}

/// The smallest power of two >= n (n >= 1).
constexpr int pow2_at_least(int n) { return 1 << clog2(n); }

}  // namespace scw::hls
