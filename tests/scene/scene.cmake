# SPDX-License-Identifier: Apache-2.0
# [scene] The synthetic stereo scenes: rays against cv::projectPoints, a rendered pair's
# disparity after rectification, the truth's eq. 5.2, the presets, the written files.
add_executable(test_scene scene/test_scene.cpp)
target_link_libraries(test_scene PRIVATE scw_test_main scw::host)
scw_warnings(test_scene)
scw_discover_tests(test_scene TEST_PREFIX "scene:")
