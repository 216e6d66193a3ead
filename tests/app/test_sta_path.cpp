// SPDX-License-Identifier: Apache-2.0
// [app] Reading Yosys sta's worst path (host/synth): start and end, the clock tree left out,
// the untimed ends rtl_synth.sh accepts, and the Fmax estimate's routing rule.
#include <catch2/catch.hpp>

#include "host/synth/timing.hpp"
#include "host/synth/yosys.hpp"

namespace {

using scw::host::synth::parse_sta_path;

// Shapes copied from Yosys 0.23 `sta` on scw modules (names shortened).
const char* kRegToReg = R"(
18. Executing STA pass (static timing analysis).
Latest arrival time in 'scw_warning' is 5196:
    5196 $auto$ff.cc:266:slice$26247 (FDRE.D)
           $auto$xilinx_dffopt.cc:347:execute$47785
    5196 $auto$xilinx_dffopt.cc:341:execute$47784 (LUT6.I3->O)
           \u_object.u_sqrt.gen_step[25].diff [25]
    4789 $auto$alumacc.cc:485:replace_alu$17768.genblk1.slice[6].genblk1.carry4 (CARRY4.CI->O)
           $auto$alumacc.cc:485:replace_alu$17768.CO [23]
    1568 $auto$ff.cc:266:slice$26841 (SRL16E.CLK->Q)
           \u_object.clk_i
      96 $auto$clkbufmap.cc:261:execute$48442 (BUFG.I->O)
           $auto$clkbufmap.cc:262:execute$48443
       0 $iopadmap$scw_warning.clk_i (IBUF.I->O)
       0   \clk_i (<primary input>)
Warning: Endpoint scw_warning.\out_last_o has no (* sta_arrival *) value.
)";

const char* kFromResetToCarry = R"(
Latest arrival time in 'scw_fifo' is 2140:
    2140 (<unknown>)
Warning: Critical-path does not terminate in a recognised endpoint.
           $auto$alumacc.cc:485:replace_alu$1746.genblk1.O [3]
    2140 $auto$alumacc.cc:485:replace_alu$1746.genblk1.slice[0].genblk1.carry4 (CARRY4.S->O)
           $auto$alumacc.cc:485:replace_alu$1746.X [1]
     891 $auto$ff.cc:266:slice$2244 (FDCE.CLR->Q)
           $abc$2410$auto$rtlil.cc:2551:NotGate$2397
     127 $abc$2410$auto$blifparse.cc:525:parse_blif$2421 (INV.I->O)
           $techmap2441$abc$2410$auto$blifparse.cc:525:parse_blif$2425.A
       0 $iopadmap$scw_fifo.rst_ni (IBUF.I->O)
       0   \rst_ni (<primary input>)

Arrival histogram:
)";

}  // namespace

TEST_CASE("a register-to-register path: launch after the clock buffer, end at the D pin",
          "[app]") {
  const auto p = parse_sta_path(kRegToReg);
  REQUIRE(p.size() == 4);
  CHECK(p.front().cell == "SRL16E.CLK->Q");
  CHECK(p.front().ps == 1568);
  CHECK(p.front().net == "$auto$alumacc.cc:485:replace_alu$17768.CO [23]");  // what Q drives
  CHECK(p[1].cell == "CARRY4.CI->O");
  CHECK(p[1].net == "\\u_object.u_sqrt.gen_step[25].diff [25]");
  CHECK(p.back().cell == "FDRE.D");
  CHECK(p.back().net == "$auto$xilinx_dffopt.cc:347:execute$47785");
  CHECK(p.back().ps == 5196);
}

TEST_CASE("a path from an input port starts at the port, an unread carry output is its end",
          "[app]") {
  const auto p = parse_sta_path(kFromResetToCarry);
  REQUIRE(p.size() == 6);
  CHECK(p.front().cell == "<primary input>");
  CHECK(p.front().net == "\\rst_ni");
  CHECK(p[1].cell == "IBUF.I->O");
  CHECK(p[3].cell == "FDCE.CLR->Q");
  CHECK(p.back().cell == "<unknown>");
  CHECK(p.back().net == "$auto$alumacc.cc:485:replace_alu$1746.genblk1.O [3]");
  CHECK(p.back().ps == 2140);
}

TEST_CASE("no report, no path", "[app]") {
  CHECK(parse_sta_path("").empty());
  CHECK(parse_sta_path("No timing paths found.\n").empty());
}

TEST_CASE("the Fmax estimate doubles the logic delay for routing", "[app]") {
  using scw::host::synth::fmax_mhz_est;
  CHECK(scw::host::synth::kRoutingAllowance == 1.0);
  CHECK(fmax_mhz_est(4000) == Approx(125.0));
  CHECK(fmax_mhz_est(scw::host::synth::kStaBudgetPs) == Approx(142.857).epsilon(1e-4));
  CHECK(fmax_mhz_est(0) == 0.0);
}
