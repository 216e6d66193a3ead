// SPDX-License-Identifier: Apache-2.0
// Latency of the RTL decision unit (rtl_models/disparity/scw_disparity_decide.sv) in clocks.
#pragma once

#include "hls/common/bits.hpp"

namespace scw::hls::disparity {

/// Clocks from a beat on scw_disparity_decide's inputs to its decide() value on disp_o, for a
/// unit built with `num_disp` candidates (its Latency parameter; the unit test checks both).
constexpr int decide_latency(int num_disp) {
  // The argmin tree has ceil(log2 num_disp) comparator levels, each registered (two
  // compare-and-select levels in a row make too long a path).
  const int tree = clog2(num_disp);
  // A: m * K[16:0] and m * K[high] (K = ceil(U 2^s / 100)) into the DSPs' M registers; beside
  //    them dmin + best, the limit and uniqueness-mask compares, the sub-pixel differences.
  // B: the DSPs' P registers; the sign picks |diff| and mx.
  // C: floor(m U / 100) = (lo + hi 2^17) >> s; quotient bit 2; 17 mx.
  // D: thresh = m + floor(m U / 100); quotient bit 1; the SADs out of their shift register.
  // E: thresh against every candidate; quotient bit 0 and the rounding compares.
  // F: the OR of every rejection and the value, registered on disp_o.
  return tree + 6;
}

}  // namespace scw::hls::disparity
