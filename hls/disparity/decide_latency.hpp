// SPDX-License-Identifier: Apache-2.0
// Latency of the RTL decision unit (rtl_models/disparity/scw_disparity_decide.sv) in clocks.
#pragma once

namespace scw::hls::disparity {

/// Clocks from a beat on scw_disparity_decide's inputs to its decide() value on disp_o, for a
/// unit built with `num_disp` candidates (its Latency parameter; the unit test checks both).
constexpr int decide_latency(int num_disp) {
  // The argmin tree has ceil(log2 num_disp) comparator levels and a register after every two
  // (the first stage takes one when the count is odd), so ceil(levels / 2) stages.
  int levels = 0;
  while ((1 << levels) < num_disp) ++levels;
  const int tree = (levels + 1) / 2;
  // A: m * U needs a multiplier of its own, registered before the next one; beside it
  //    dmin + best, the limit and uniqueness-mask compares, and the sub-pixel differences.
  // B: floor(m * U / 100) by a reciprocal multiply (the second multiplier); beside it two
  //    restoring-division steps of the sub-pixel fraction.
  // C: thresh = m + floor(m * U / 100) then its compare against every candidate (an adder then
  //    a comparator); beside it the last division step and its remainder compare.
  // D: the OR over every candidate's rejection and the output select, registered on disp_o.
  return tree + 4;
}

}  // namespace scw::hls::disparity
