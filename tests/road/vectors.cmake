# SPDX-License-Identifier: Apache-2.0
# A plain SystemVerilog testbench replays each committed road set against scw_road (idle input
# cycles, output backpressure, the fit holding each sof), as a user would in their own simulator.
foreach(set street implausible)
  add_test(NAME "vectors:SystemVerilog testbench replays road/${set}"
           COMMAND bash "${CMAKE_CURRENT_SOURCE_DIR}/road/tb/replay_road.sh"
                   "${PROJECT_SOURCE_DIR}/vectors/road/${set}" tb_replay_road_${set}
           WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
  set_tests_properties("vectors:SystemVerilog testbench replays road/${set}"
                       PROPERTIES PASS_REGULAR_EXPRESSION "PASS: [0-9]+ beats match")
endforeach()
