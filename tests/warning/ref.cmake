# SPDX-License-Identifier: Apache-2.0
# Warning: the fixed-point arithmetic against the floating-point Eigen reference (every disparity
# code over an image grid, the thesis's worked example), to_fixed's errors, and the Fig. 5.11 b
# overlay.
add_executable(test_warning_ref ${CMAKE_CURRENT_SOURCE_DIR}/warning/test_warning_ref.cpp
                                ${CMAKE_CURRENT_SOURCE_DIR}/warning/test_warning_overlay.cpp)
target_link_libraries(test_warning_ref PRIVATE scw_test_main scw::host)
scw_warnings(test_warning_ref)
scw_discover_tests(test_warning_ref TEST_PREFIX "warning:")
