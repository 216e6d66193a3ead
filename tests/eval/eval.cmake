# SPDX-License-Identifier: Apache-2.0
# [eval] `scw eval`'s comparison, inputs, JSON, table and plots on hand-made truth and results.
add_executable(test_eval ${CMAKE_CURRENT_LIST_DIR}/test_eval.cpp)
target_link_libraries(test_eval PRIVATE scw_test_main scw::host)
scw_warnings(test_eval)
scw_discover_tests(test_eval TEST_PREFIX "eval:")
