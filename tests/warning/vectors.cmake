# SPDX-License-Identifier: Apache-2.0
# A plain SystemVerilog testbench replays each committed warning set against scw_warning (idle
# input cycles, output backpressure), as a user would in their own simulator.
if(EXISTS "${PROJECT_SOURCE_DIR}/rtl_models/warning/scw_warning.sv")
  foreach(set thesis random malformed)
    add_test(NAME "vectors:SystemVerilog testbench replays warning/${set}"
             COMMAND bash "${CMAKE_CURRENT_SOURCE_DIR}/warning/tb/replay_warning.sh"
                     "${PROJECT_SOURCE_DIR}/vectors/warning/${set}" tb_replay_warning_${set}
             WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
    set_tests_properties("vectors:SystemVerilog testbench replays warning/${set}"
                         PROPERTIES PASS_REGULAR_EXPRESSION "PASS: [0-9]+ beats match")
  endforeach()
endif()
