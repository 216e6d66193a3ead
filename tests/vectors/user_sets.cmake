# SPDX-License-Identifier: Apache-2.0
# Vector sets from a user's own pair (scw vectors disparity --left/--right): the Tsukuba preset's
# crop given as files and --roi must make the preset's streams byte for byte, and a frame larger
# than the vector build must be refused naming --roi.
set(_tsukuba "${PROJECT_SOURCE_DIR}/data/tsukuba")

# Replays the set a fixture made in both simulators: "vectors:TITLE in verilator|icarus".
function(scw_replay_user_set set fixture title)
  foreach(_sim verilator icarus)
    add_test(NAME "vectors:${title} in ${_sim}"
             COMMAND bash "${PROJECT_SOURCE_DIR}/scripts/replay.sh" ${set}
                     "replay/${_sim}/${set}" --simulator ${_sim}
             WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
    set_tests_properties("vectors:${title} in ${_sim}"
                         PROPERTIES FIXTURES_REQUIRED ${fixture} LABELS "vectors;${_sim}"
                                    TIMEOUT 300)
  endforeach()
endfunction()
add_test(NAME "vectors:scw vectors disparity from a user's pair equals the tsukuba preset's streams"
         COMMAND bash -c "rm -rf user_tsukuba && '$<TARGET_FILE:scw>' vectors disparity \
                          --left '${_tsukuba}/scene1.row3.col3.ppm' \
                          --right '${_tsukuba}/scene1.row3.col4.ppm' --roi 144 112 96 48 \
                          --window 9 --mode opencv --out user_tsukuba && \
                          for f in left.hex right.hex expected.hex expected.png; do \
                            cmp \"user_tsukuba/$f\" '${PROJECT_SOURCE_DIR}/vectors/disparity/tsukuba/'\"$f\" || exit 1; \
                          done"
         WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
add_test(NAME "vectors:scw vectors disparity refuses a pair larger than the build, naming --roi"
         COMMAND $<TARGET_FILE:scw> vectors disparity --left "${_tsukuba}/scene1.row3.col3.ppm"
                 --right "${_tsukuba}/scene1.row3.col4.ppm" --out user_too_large
         WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
set_tests_properties("vectors:scw vectors disparity refuses a pair larger than the build, naming --roi"
                     PROPERTIES PASS_REGULAR_EXPRESSION "does not fit the vector build .*give --roi X Y W H")

# A set too large to commit, made on demand at the thesis build: a 640 x 240 band of the bundled
# chessboard pair rectified with its calibration (153,600 beats, about 2.9 MB), verified against
# its manifest, then replayed in both simulators. (The whole 640 x 480 image needs 81 raw rows in
# flight, more than the thesis build's 64; the command says so.)
add_test(NAME "vectors:scw vectors rectify --config thesis makes a chessboard set and verifies it"
         COMMAND bash -c "rm -rf thesis_rectify && '$<TARGET_FILE:scw>' vectors rectify \
                          --preset chessboard_left --config thesis --ppc 1 --engine cpp \
                          --stalls none --roi 0 120 --size 640 240 \
                          --data-dir '${PROJECT_SOURCE_DIR}/data/chessboard' --out thesis_rectify \
                          && '$<TARGET_FILE:scw>' vectors verify thesis_rectify"
         WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
set_tests_properties("vectors:scw vectors rectify --config thesis makes a chessboard set and verifies it"
                     PROPERTIES FIXTURES_SETUP scw_thesis_rectify_set)
scw_replay_user_set(thesis_rectify scw_thesis_rectify_set "the thesis-size chessboard rectify set replays")

# A labelling set from a user's disparity map: the Tsukuba pair through `scw disparity --out16`,
# a 64 x 48 crop of it, replayed in both simulators; an 8-bit file is refused naming --out16.
add_test(NAME "vectors:scw vectors labelling from a user's disparity map makes a set"
         COMMAND bash -c "rm -rf user_labelling && '$<TARGET_FILE:scw>' disparity \
                          --left '${_tsukuba}/scene1.row3.col3.ppm' \
                          --right '${_tsukuba}/scene1.row3.col4.ppm' --window 9 --min-disp 0 \
                          --max-disp 15 --mode opencv --out user_d8.png --out16 user_d16.png && \
                          '$<TARGET_FILE:scw>' vectors labelling --disparity user_d16.png \
                          --roi 144 112 64 48 --tiles 2 2 --min-area 20 --out user_labelling && \
                          '$<TARGET_FILE:scw>' vectors verify user_labelling"
         WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
set_tests_properties("vectors:scw vectors labelling from a user's disparity map makes a set"
                     PROPERTIES FIXTURES_SETUP scw_user_labelling_set)
scw_replay_user_set(user_labelling scw_user_labelling_set "the labelling set from a user's map replays")
add_test(NAME "vectors:scw vectors labelling refuses an 8-bit map, naming --out16"
         COMMAND $<TARGET_FILE:scw> vectors labelling
                 --disparity "${_tsukuba}/truedisp.row3.col3.pgm" --out user_8bit
         WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
set_tests_properties("vectors:scw vectors labelling refuses an 8-bit map, naming --out16"
                     PROPERTIES PASS_REGULAR_EXPRESSION "not a 16-bit one-channel image.*--out16")

# A rectify set from a user's raw pair and calibration: the bundled chessboard files given as
# --left/--right/--calib make the chessboard_right preset's streams byte for byte.
set(_chess "${PROJECT_SOURCE_DIR}/data/chessboard")
add_test(NAME "vectors:scw vectors rectify from a user's raw pair and calibration equals the chessboard preset's streams"
         COMMAND bash -c "rm -rf user_rectify && '$<TARGET_FILE:scw>' vectors rectify \
                          --left '${_chess}/left01.jpg' --right '${_chess}/right01.jpg' \
                          --calib '${_chess}/derived_stereo_calibration_helper.yml' \
                          --camera right --out user_rectify && \
                          for f in input.hex map.hex expected.hex expected.png; do \
                            cmp \"user_rectify/$f\" '${PROJECT_SOURCE_DIR}/vectors/rectify/chessboard_right/'\"$f\" || exit 1; \
                          done"
         WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
add_test(NAME "vectors:scw vectors rectify refuses a pair not of the calibration's size"
         COMMAND $<TARGET_FILE:scw> vectors rectify --left "${_chess}/left01.jpg"
                 --right "${_tsukuba}/scene1.row3.col4.ppm"
                 --calib "${_chess}/derived_stereo_calibration_helper.yml" --out user_badsize
         WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
set_tests_properties("vectors:scw vectors rectify refuses a pair not of the calibration's size"
                     PROPERTIES PASS_REGULAR_EXPRESSION "is 384x288, the calibration .* is for 640x480 images")

# A warning set from a user's object tables: a labelling set's object and status CSVs (the
# committed shapes set, 5 frames) on a rig of one's own, verified, then replayed in both simulators.
add_test(NAME "vectors:scw vectors warning from a user's object tables makes a set"
         COMMAND bash -c "rm -rf user_warning && '$<TARGET_FILE:scw>' vectors warning \
                          --objects '${PROJECT_SOURCE_DIR}/vectors/labelling/shapes/expected_objects.csv' \
                          --status '${PROJECT_SOURCE_DIR}/vectors/labelling/shapes/expected_status.csv' \
                          --image-size 64 48 --focal 60 --baseline 0.3 --out user_warning && \
                          '$<TARGET_FILE:scw>' vectors verify user_warning"
         WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
set_tests_properties("vectors:scw vectors warning from a user's object tables makes a set"
                     PROPERTIES FIXTURES_SETUP scw_user_warning_set)
scw_replay_user_set(user_warning scw_user_warning_set "the warning set from a user's tables replays")
add_test(NAME "vectors:scw vectors warning refuses a value wider than its field, naming line and column"
         COMMAND bash -c "sed '2s/^0,0,1,1600,/0,0,1,99999999999,/' \
                          '${PROJECT_SOURCE_DIR}/vectors/labelling/shapes/expected_objects.csv' > wide.csv && \
                          '$<TARGET_FILE:scw>' vectors warning --objects wide.csv --out user_wide"
         WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
set_tests_properties("vectors:scw vectors warning refuses a value wider than its field, naming line and column"
                     PROPERTIES PASS_REGULAR_EXPRESSION "wide.csv:2: area '99999999999' does not fit the field's 32 bits")
