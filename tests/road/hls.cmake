# SPDX-License-Identifier: Apache-2.0
# [hls] The road stage's kernel against the floating-point reference, its fit against doubles,
# the cycle model against the frame function.
add_executable(test_road_hls road/test_road_hls.cpp)
target_link_libraries(test_road_hls PRIVATE scw_test_main scw::sim scw::host)
scw_warnings(test_road_hls)
scw_discover_tests(test_road_hls TEST_PREFIX "road:")
