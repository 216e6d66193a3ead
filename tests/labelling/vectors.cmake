# SPDX-License-Identifier: Apache-2.0
# A plain SystemVerilog testbench replays each committed labelling set against scw_labelling
# (idle input cycles, output backpressure), as a user would in their own simulator.
if(EXISTS "${PROJECT_SOURCE_DIR}/rtl_models/labelling/scw_labelling.sv")
  foreach(set shapes tsukuba overflow)
    add_test(NAME "vectors:SystemVerilog testbench replays labelling/${set}"
             COMMAND bash "${CMAKE_CURRENT_SOURCE_DIR}/labelling/tb/replay_labelling.sh"
                     "${PROJECT_SOURCE_DIR}/vectors/labelling/${set}" tb_replay_labelling_${set}
             WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
    set_tests_properties("vectors:SystemVerilog testbench replays labelling/${set}"
                         PROPERTIES PASS_REGULAR_EXPRESSION "PASS: [0-9]+ words match")
  endforeach()
endif()
