# SPDX-License-Identifier: Apache-2.0
# [app] Reading Yosys sta's worst path and the Fmax rule (host/synth).
add_executable(test_sta_path app/test_sta_path.cpp)
target_link_libraries(test_sta_path PRIVATE scw_test_main scw::host)
scw_warnings(test_sta_path)
scw_discover_tests(test_sta_path TEST_PREFIX "app:")
