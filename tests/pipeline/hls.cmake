# SPDX-License-Identifier: Apache-2.0
# [hls] The pipeline's HLS top (DATAFLOW over the stage tops) against the clocked C++ chain:
# C++ only, no Verilated model.
add_executable(test_pipeline_hls pipeline/test_pipeline_hls.cpp)
target_link_libraries(test_pipeline_hls PRIVATE scw_test_main scw::sim scw::host)
scw_warnings(test_pipeline_hls)
scw_discover_tests(test_pipeline_hls TEST_PREFIX "pipeline:")
# sim::PipelineChain names the Verilated engines too (never built here, NoRtl): their headers
# include verilated.h, so the test needs Verilator's include path but none of its libraries.
target_include_directories(test_pipeline_hls SYSTEM PRIVATE ${VERILATOR_ROOT}/include
                                                            ${VERILATOR_ROOT}/include/vltstd)
