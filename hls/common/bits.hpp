// SPDX-License-Identifier: Apache-2.0
// SystemVerilog's $clog2 at compile time: the widths and tree depths that the C++ models and the
// RTL derive from the same parameters, written once.
#pragma once

namespace scw::hls {

/// ceil(log2 v): the bits of an address of v entries, as $clog2(v) (0 for v <= 1).
constexpr int clog2(long long v) {
  int b = 0;
  while ((1LL << b) < v) ++b;
  return b;
}

}  // namespace scw::hls
