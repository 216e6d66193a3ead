# SPDX-License-Identifier: Apache-2.0
# [app] Object classification (thesis 5.3.3) and `scw train`, whose command source is compiled in
# so its options are tested through CLI11 as main.cpp registers them.
add_executable(test_classify app/test_classify.cpp ${PROJECT_SOURCE_DIR}/host/cli/cmd_train.cpp)
target_link_libraries(test_classify PRIVATE scw_test_main scw::host CLI11::CLI11)
scw_warnings(test_classify)
scw_discover_tests(test_classify TEST_PREFIX "app:")
