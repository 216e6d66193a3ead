// SPDX-License-Identifier: Apache-2.0
// The clock a path of Yosys `sta` logic delay allows: the routing allowance, written once.
#pragma once

namespace scw::host::synth {

/// Routing delay assumed per ps of logic delay. Yosys `sta` adds the prjxray 7-series cell
/// delays with zero routing; on 7-series a placed and routed path typically spends about as much
/// in its nets as in its cells (docs/timing.md), so a path of L ps of logic is taken to need
/// L * (1 + kRoutingAllowance) ps of clock period.
inline constexpr double kRoutingAllowance = 1.0;

/// The timing budget for one path of logic (ps) at the thesis's 125 MHz: half of the 8 ns
/// period minus a margin, so routing as costly as the logic still closes the clock. CI checks
/// every module against it (rtl_models/CMakeLists.txt reads this number).
inline constexpr int kStaBudgetPs = 3500;

/// Estimated Fmax in MHz of a path with `logic_ps` of cell delay.
inline double fmax_mhz_est(double logic_ps) {
  return logic_ps > 0 ? 1.0e6 / (logic_ps * (1.0 + kRoutingAllowance)) : 0.0;
}

}  // namespace scw::host::synth
