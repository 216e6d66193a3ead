# SPDX-License-Identifier: Apache-2.0
# [app] The tracker's rules (thesis 5.3.3), in mean-speed and Kalman mode.
add_executable(test_track app/test_track.cpp)
target_link_libraries(test_track PRIVATE scw_test_main scw::host)
scw_warnings(test_track)
scw_discover_tests(test_track TEST_PREFIX "app:")
