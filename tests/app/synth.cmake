# SPDX-License-Identifier: Apache-2.0
# `scw synth`: two small stages through Yosys with the JSON checked field by field, and an
# unknown build refused with a message naming the builds. The checks are CMake scripts
# (synth_check.cmake) so the tests need nothing beyond cmake, bash and Yosys.
include(${PROJECT_SOURCE_DIR}/cmake/ScwTiming.cmake)
scw_sta_budget(_scw_budget)
add_test(NAME "app:cli synth at the small build writes a JSON entry per module"
         COMMAND ${CMAKE_COMMAND} -DSCW=$<TARGET_FILE:scw> -DMODE=small -DBUDGET=${_scw_budget}
                 -DWORK=${CMAKE_CURRENT_BINARY_DIR}/cli_synth
                 -P ${CMAKE_CURRENT_LIST_DIR}/synth_check.cmake)
set_tests_properties("app:cli synth at the small build writes a JSON entry per module"
                     PROPERTIES LABELS "yosys" TIMEOUT 300 COST 30)
add_test(NAME "app:cli synth refuses an unknown config and names the configs"
         COMMAND ${CMAKE_COMMAND} -DSCW=$<TARGET_FILE:scw> -DMODE=unknown_config
                 -DWORK=${CMAKE_CURRENT_BINARY_DIR}/cli_synth_bad
                 -P ${CMAKE_CURRENT_LIST_DIR}/synth_check.cmake)
