# SPDX-License-Identifier: Apache-2.0
# [hls] The labelling model against the flood-fill reference.
add_executable(test_labelling_hls labelling/test_labelling_hls.cpp)
target_link_libraries(test_labelling_hls PRIVATE scw_test_main scw::sim scw::host)
target_compile_definitions(test_labelling_hls PRIVATE SCW_DATA_DIR="${PROJECT_SOURCE_DIR}/data")
scw_warnings(test_labelling_hls)
scw_discover_tests(test_labelling_hls TEST_PREFIX "labelling:")

# [hls] The labelling stage with 2 and 4 lanes against one lane and the flood fill.
add_executable(test_labelling_lanes labelling/test_labelling_lanes.cpp)
target_link_libraries(test_labelling_lanes PRIVATE scw_test_main scw::sim scw::host)
target_compile_definitions(test_labelling_lanes PRIVATE SCW_DATA_DIR="${PROJECT_SOURCE_DIR}/data")
scw_warnings(test_labelling_lanes)
scw_discover_tests(test_labelling_lanes TEST_PREFIX "labelling:")
