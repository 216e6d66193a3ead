# SPDX-License-Identifier: Apache-2.0
# [hls] The ground-removal model against the plain-loop reference (synthetic roads, random maps,
# Tsukuba), its latency, the frame function and broken frames.
add_executable(test_ground_hls ground/test_ground_hls.cpp)
target_link_libraries(test_ground_hls PRIVATE scw_test_main scw::sim scw::host)
target_compile_definitions(test_ground_hls PRIVATE SCW_DATA_DIR="${PROJECT_SOURCE_DIR}/data")
scw_warnings(test_ground_hls)
scw_discover_tests(test_ground_hls TEST_PREFIX "ground:")
