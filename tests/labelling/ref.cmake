# SPDX-License-Identifier: Apache-2.0
# Labelling: the flood-fill reference against cv::connectedComponentsWithStats, the join rule and
# descriptors by hand, Hu moments against cv::HuMoments, and Tsukuba's ground truth.
add_executable(test_labelling_ref ${CMAKE_CURRENT_SOURCE_DIR}/labelling/test_labelling_ref.cpp)
target_link_libraries(test_labelling_ref PRIVATE scw_test_main scw::host)
target_compile_definitions(test_labelling_ref PRIVATE SCW_DATA_DIR="${PROJECT_SOURCE_DIR}/data")
scw_warnings(test_labelling_ref)
scw_discover_tests(test_labelling_ref TEST_PREFIX "labelling:")
