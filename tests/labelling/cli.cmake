# SPDX-License-Identifier: Apache-2.0
# Labelling, host side: thesis 3.2's post-processing and pictures, and `scw segment` end to end.
add_executable(test_labelling_post ${CMAKE_CURRENT_SOURCE_DIR}/labelling/test_labelling_post.cpp)
target_link_libraries(test_labelling_post PRIVATE scw_test_main scw::host)
scw_warnings(test_labelling_post)
scw_discover_tests(test_labelling_post TEST_PREFIX "labelling:")

# `scw segment` on Tsukuba's ground truth (8-bit, disparity x 16): the three files, checked by the
# hidden "[.segment-output]" case of test_labelling_post (labels.png 16-bit, its largest label =
# the rows of objects.csv, areas and first pixels); the same labels on a 4 x 2 tile grid; the
# post-processing outputs; and clear errors (exit != 0, a message on stderr).
set(scw_truth "${PROJECT_SOURCE_DIR}/data/tsukuba/truedisp.row3.col3.pgm")
add_test(NAME "labelling:cli segments Tsukuba's ground truth"
         COMMAND bash -c "rm -rf cli_segment && '$<TARGET_FILE:scw>' segment \
                          --disparity '${scw_truth}' --out-dir cli_segment && \
                          for f in labels.png objects.csv labels_color.png; do \
                          test -s cli_segment/$f || exit 1; done && \
                          SCW_SEGMENT_OUT=cli_segment '$<TARGET_FILE:test_labelling_post>' \
                          '[.segment-output]'"
         WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
add_test(NAME "labelling:cli labels do not depend on the tile grid"
         COMMAND bash -c "rm -rf cli_segment_1x1 cli_segment_4x2 && \
                          '$<TARGET_FILE:scw>' segment --disparity '${scw_truth}' \
                          --out-dir cli_segment_1x1 && \
                          '$<TARGET_FILE:scw>' segment --disparity '${scw_truth}' --tiles 4x2 \
                          --out-dir cli_segment_4x2 && \
                          cmp cli_segment_1x1/objects.csv cli_segment_4x2/objects.csv && \
                          cmp cli_segment_1x1/labels.png cli_segment_4x2/labels.png"
         WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
add_test(NAME "labelling:cli post-processing writes regions.png and regions.csv"
         COMMAND bash -c "rm -rf cli_segment_post && '$<TARGET_FILE:scw>' segment \
                          --disparity '${scw_truth}' --min-area 20 --post \
                          --out-dir cli_segment_post && \
                          for f in labels.png objects.csv labels_color.png regions.png \
                          regions.csv; do test -s cli_segment_post/$f || exit 1; done"
         WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
add_test(NAME "labelling:cli segments a 16-bit map from scw disparity --out16"
         COMMAND bash -c "rm -rf cli_segment16 && '$<TARGET_FILE:scw>' disparity \
                          --left '${PROJECT_SOURCE_DIR}/data/tsukuba/scene1.row3.col3.ppm' \
                          --right '${PROJECT_SOURCE_DIR}/data/tsukuba/scene1.row3.col4.ppm' \
                          --window 9 --min-disp 0 --max-disp 15 --mode opencv \
                          --out cli_segment16/d8.png --out16 cli_segment16/d16.png && \
                          '$<TARGET_FILE:scw>' segment --disparity cli_segment16/d16.png \
                          --min-area 50 --tiles 2x2 --out-dir cli_segment16 && \
                          SCW_SEGMENT_OUT=cli_segment16 '$<TARGET_FILE:test_labelling_post>' \
                          '[.segment-output]'"
         WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
add_test(NAME "labelling:cli refuses a missing file"
         COMMAND bash -c "if '$<TARGET_FILE:scw>' segment --disparity no_such_map.png \
                          --out-dir cli_segment_missing 2> cli_segment_missing.err; then exit 1; \
                          fi; cat cli_segment_missing.err; \
                          grep -q 'no_such_map.png' cli_segment_missing.err"
         WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
add_test(NAME "labelling:cli refuses a colour image"
         COMMAND bash -c "if '$<TARGET_FILE:scw>' segment \
                          --disparity '${PROJECT_SOURCE_DIR}/data/tsukuba/scene1.row3.col3.ppm' \
                          --out-dir cli_segment_colour 2> cli_segment_colour.err; then exit 1; \
                          fi; cat cli_segment_colour.err; \
                          grep -q 'scene1.row3.col3.ppm.* has 3 channel(s) .*single-channel' \
                          cli_segment_colour.err"
         WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
add_test(NAME "labelling:cli refuses a bad tile grid"
         COMMAND bash -c "if '$<TARGET_FILE:scw>' segment --disparity '${scw_truth}' \
                          --tiles 4by2 --out-dir cli_segment_tiles 2> cli_segment_tiles.err; \
                          then exit 1; fi; cat cli_segment_tiles.err; \
                          grep -q \"tiles '4by2' is not of the form CxR\" cli_segment_tiles.err"
         WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
