# SPDX-License-Identifier: Apache-2.0
# [hls] The warning model against a plain fold of its per-object arithmetic.
add_executable(test_warning_hls warning/test_warning_hls.cpp)
target_link_libraries(test_warning_hls PRIVATE scw_test_main scw::sim scw::host)
scw_warnings(test_warning_hls)
scw_discover_tests(test_warning_hls TEST_PREFIX "warning:")
