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
# The C-synthesis top of the pipeline (hls/tops) built at the small build into the same test, so
# one case runs frames through scw_pipeline_top as a vendor C-simulation test bench would.
target_sources(test_pipeline_hls PRIVATE ${PROJECT_SOURCE_DIR}/hls/tops/scw_pipeline_top.cpp)
target_compile_definitions(test_pipeline_hls PRIVATE
                           "SCW_HLS_BUILD=scw::hls::pipeline::SmallPipeline<1>")

# Every stage's C-synthesis top, built at the small build, against the links of the clocked chain.
add_executable(test_hls_tops pipeline/test_hls_tops.cpp)
foreach(stage frame_check map_grid rectify disparity road ground labelling warning)
  target_sources(test_hls_tops PRIVATE ${PROJECT_SOURCE_DIR}/hls/tops/scw_${stage}_top.cpp)
endforeach()
target_link_libraries(test_hls_tops PRIVATE scw_test_main scw::sim scw::host)
target_compile_definitions(test_hls_tops PRIVATE "SCW_HLS_BUILD=scw::hls::pipeline::SmallPipeline<1>")
target_include_directories(test_hls_tops SYSTEM PRIVATE ${VERILATOR_ROOT}/include
                                                        ${VERILATOR_ROOT}/include/vltstd)
scw_warnings(test_hls_tops)
scw_discover_tests(test_hls_tops TEST_PREFIX "hls:")

# Every C-synthesis top compiled as an HLS tool's front end takes it, at the thesis build:
# __SYNTHESIS__ defined (the host's checks and the second-pass map left out) and no exceptions
# (a `throw` is a compile error), then its object must reference no heap and no throw
# (tests/common/check_synthesis_objects.cmake): no heap, no exceptions, as docs/hls.md claims.
file(GLOB scw_hls_tops CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/hls/tops/*.cpp)
add_library(scw_hls_tops_synthesis OBJECT ${scw_hls_tops})
target_link_libraries(scw_hls_tops_synthesis PRIVATE scw::hls)
target_compile_definitions(scw_hls_tops_synthesis PRIVATE __SYNTHESIS__)
target_compile_options(scw_hls_tops_synthesis PRIVATE -fno-exceptions -O1)
scw_warnings(scw_hls_tops_synthesis)
add_test(NAME "hls:the C-synthesis tops compile without exceptions and reference no heap"
         COMMAND ${CMAKE_COMMAND} -DNM=${CMAKE_NM} "-DOBJECTS=$<TARGET_OBJECTS:scw_hls_tops_synthesis>"
                 -P ${PROJECT_SOURCE_DIR}/tests/common/check_synthesis_objects.cmake)
