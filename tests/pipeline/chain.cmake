# SPDX-License-Identifier: Apache-2.0
# [pipeline] The whole pipeline at the small build (scw_pipeline_build in sim/CMakeLists.txt): the C++
# chain, the chain of Verilated blocks and the Verilated scw_pipeline top, clock for clock.
add_executable(test_pipeline_chain pipeline/test_pipeline_chain.cpp)
target_link_libraries(test_pipeline_chain PRIVATE scw_test_main scw::sim scw::host
                                                  scw_rtl_pipeline_small)
target_compile_definitions(test_pipeline_chain PRIVATE SCW_DATA_DIR="${PROJECT_SOURCE_DIR}/data")
scw_warnings(test_pipeline_chain)
scw_discover_tests(test_pipeline_chain TEST_PREFIX "pipeline:")

# `scw run --engine rtl`'s engine against the C++ models through the application chain.
add_executable(test_pipeline_run pipeline/test_pipeline_run.cpp)
target_link_libraries(test_pipeline_run PRIVATE scw_test_main scw::host scw_rtl_engine)
target_compile_definitions(test_pipeline_run PRIVATE SCW_DATA_DIR="${PROJECT_SOURCE_DIR}/data")
scw_warnings(test_pipeline_run)
scw_discover_tests(test_pipeline_run TEST_PREFIX "pipeline:")

# `scw sim` end to end: the small build all RTL under random stalls, the floating-point chain
# beside it, the JSON report; and a bad option named.
add_test(NAME "pipeline:cli sim runs the small build in RTL, agrees with the reference, writes JSON"
         COMMAND bash -c "rm -f cli_sim.json && '$<TARGET_FILE:scw>' sim --config small \
                          --frames 2 --engine rtl --stalls random:3 --reference \
                          --json cli_sim.json > cli_sim.txt 2> cli_sim.err && \
                          grep -q 'frame period T_P' cli_sim.txt && \
                          grep -q ': agrees with the pipeline' cli_sim.txt && \
                          grep -q '\"agrees\": true' cli_sim.json && \
                          grep -q '\"period_cycles\"' cli_sim.json"
         WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
# `scw sim --engine rtl-top` (the scw_pipeline top as one model) reports the chain's cycles,
# frame timing and results, with the sources and sinks stalling.
foreach(p 1 2)
  add_test(NAME "pipeline:cli sim --engine rtl-top reports what the chain of blocks does, P = ${p}"
           COMMAND ${CMAKE_COMMAND} -DSCW=$<TARGET_FILE:scw> -DPPC=${p} -DSTALLS=random:5
                   -P ${CMAKE_CURRENT_SOURCE_DIR}/pipeline/sim_engines_agree.cmake
           WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
endforeach()
add_test(NAME "pipeline:cli sim and run refuse the thread counts they cannot use"
         COMMAND bash -c "! '$<TARGET_FILE:scw>' sim --config small --threads 3 2> cli_sim_t3.err && \
                          grep -q -- '--threads 3: use 1 or 2' cli_sim_t3.err && \
                          ! '$<TARGET_FILE:scw>' sim --config small --engine rtl-top --threads 2 \
                            2> cli_sim_t2.err && \
                          grep -q 'one Verilated model on one thread' cli_sim_t2.err && \
                          ! '$<TARGET_FILE:scw>' run --threads 2 --rectified --focal 615 \
                            --baseline 0.1 --left '${PROJECT_SOURCE_DIR}/data/tsukuba/scene1.row3.col3.ppm' \
                            --right '${PROJECT_SOURCE_DIR}/data/tsukuba/scene1.row3.col4.ppm' \
                            --out-dir cli_run_t2 2> cli_run_t2.err && \
                          grep -q 'give --engine rtl with it' cli_run_t2.err && \
                          ! '$<TARGET_FILE:scw>' run --threads 3 --rectified --focal 615 \
                            --baseline 0.1 --left '${PROJECT_SOURCE_DIR}/data/tsukuba/scene1.row3.col3.ppm' \
                            --right '${PROJECT_SOURCE_DIR}/data/tsukuba/scene1.row3.col4.ppm' \
                            --out-dir cli_run_t3 2> cli_run_t3.err && \
                          grep -q -- '--threads 3: use 1 or 2' cli_run_t3.err"
         WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
add_test(NAME "pipeline:cli sim refuses an unknown configuration and names the two"
         COMMAND bash -c "! '$<TARGET_FILE:scw>' sim --config big 2> cli_sim_bad.err && \
                          grep -q 'use thesis (1280 x 480' cli_sim_bad.err"
         WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
# The refusal is the only line: nothing is set up or announced first.
add_test(NAME "pipeline:cli sim --rtl-stages takes a comma list, blanks allowed, and names an unknown block"
         COMMAND bash -c "! '$<TARGET_FILE:scw>' sim --config small --frames 1 \
                            --rtl-stages 'warning, nope' 2> cli_sim_stages.err && \
                          grep -q \"no block 'nope'\" cli_sim_stages.err && \
                          test $(wc -l < cli_sim_stages.err) -eq 1"
         WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
