# SPDX-License-Identifier: Apache-2.0
# [pipeline] The whole pipeline at the small build (sim/builds/pipeline_small.cmake): the C++
# chain, the chain of Verilated blocks and the Verilated scw_pipeline top, clock for clock.
add_executable(test_pipeline_chain pipeline/test_pipeline_chain.cpp)
target_link_libraries(test_pipeline_chain PRIVATE scw_test_main scw::sim scw::host
                                                  scw_rtl_pipeline_small)
target_compile_definitions(test_pipeline_chain PRIVATE SCW_DATA_DIR="${PROJECT_SOURCE_DIR}/data")
scw_warnings(test_pipeline_chain)
catch_discover_tests(test_pipeline_chain TEST_PREFIX "pipeline:")

# `scw run --engine rtl`'s engine against the C++ models through the application chain.
add_executable(test_pipeline_run pipeline/test_pipeline_run.cpp)
target_link_libraries(test_pipeline_run PRIVATE scw_test_main scw::host scw_rtl_engine)
target_compile_definitions(test_pipeline_run PRIVATE SCW_DATA_DIR="${PROJECT_SOURCE_DIR}/data")
scw_warnings(test_pipeline_run)
catch_discover_tests(test_pipeline_run TEST_PREFIX "pipeline:")
