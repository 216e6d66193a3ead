# SPDX-License-Identifier: Apache-2.0
# Vector sets from a user's own pair (scw vectors disparity --left/--right): the Tsukuba preset's
# crop given as files and --roi must make the preset's streams byte for byte, and a frame larger
# than the vector build must be refused naming --roi.
set(_tsukuba "${PROJECT_SOURCE_DIR}/data/tsukuba")

# Replays the set a fixture made: "vectors:TITLE in <simulator>", in Icarus Verilog unless
# SIMULATORS names others. The committed sets replay every testbench in both simulators
# (tests/vectors/replay.cmake), so a user's set needs only the 4-state one, the Yosys-written
# block, to show the generator's output and the testbench's generality; a Verilator build of a
# testbench costs twice an Icarus one on a small set. A long set whose block configuration a
# committed set already replays in Icarus (the same Yosys-written block at the same parameters)
# replays in Verilator instead, where it takes a quarter to a seventh of Icarus's time (a two-frame
# small-build disparity set 4 s against 29 s; docs/performance.md, "CI time").
function(scw_replay_user_set set fixture title)
  cmake_parse_arguments(PARSE_ARGV 3 arg "" "" "SIMULATORS")
  set(_sims icarus)
  if(arg_SIMULATORS)
    set(_sims ${arg_SIMULATORS})
  endif()
  foreach(_sim IN LISTS _sims)
    add_test(NAME "vectors:${title} in ${_sim}"
             COMMAND bash "${PROJECT_SOURCE_DIR}/scripts/replay.sh" ${set}
                     "replay/${_sim}/${set}" --simulator ${_sim}
             WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
    set_tests_properties("vectors:${title} in ${_sim}"
                         PROPERTIES FIXTURES_REQUIRED ${fixture} LABELS "vectors;${_sim}"
                                    TIMEOUT 300 ENVIRONMENT "${SCW_REPLAY_ENV}")
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
                     PROPERTIES PASS_REGULAR_EXPRESSION "does not fit the vectors build .*give --roi X Y W H")

# A set too large to commit, made on demand at the thesis build: a 640 x 240 band of the bundled
# chessboard pair rectified with its calibration (153,600 beats, about 2.9 MB), verified against
# its manifest, then replayed in Verilator. Its Icarus replay, 26 to 39 s of full-size simulation,
# is a benchmark like the thesis-size Yosys runs: listed, and disabled unless
# -DSCW_REPLAY_THESIS=ON. (The whole 640 x 480 image needs 81 raw rows in flight, more than the
# thesis build's 64; the command says so.)
add_test(NAME "vectors:scw vectors rectify --config thesis makes a chessboard set and verifies it"
         COMMAND bash -c "rm -rf thesis_rectify && '$<TARGET_FILE:scw>' vectors rectify \
                          --preset chessboard_left --config thesis --ppc 1 --engine cpp \
                          --stalls none --roi 0 120 --size 640 240 \
                          --data-dir '${PROJECT_SOURCE_DIR}/data/chessboard' --out thesis_rectify \
                          && '$<TARGET_FILE:scw>' vectors verify thesis_rectify"
         WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
set_tests_properties("vectors:scw vectors rectify --config thesis makes a chessboard set and verifies it"
                     PROPERTIES FIXTURES_SETUP scw_thesis_rectify_set)
scw_replay_user_set(thesis_rectify scw_thesis_rectify_set
                    "the thesis-size chessboard rectify set replays"
                    SIMULATORS verilator icarus)
if(NOT SCW_REPLAY_THESIS)
  set_tests_properties("vectors:the thesis-size chessboard rectify set replays in icarus"
                       PROPERTIES DISABLED ON)
endif()

# A labelling set from a user's disparity map: the Tsukuba pair through `scw disparity --out16`,
# a 64 x 48 crop of it, replayed in Icarus; an 8-bit file is refused naming --out16.
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
# committed shapes set, 5 frames) on a rig of one's own at the small build (a reciprocal table
# below 32 px), verified, then replayed in Icarus.
add_test(NAME "vectors:scw vectors warning from a user's object tables makes a set"
         COMMAND bash -c "rm -rf user_warning && '$<TARGET_FILE:scw>' vectors warning \
                          --objects '${PROJECT_SOURCE_DIR}/vectors/labelling/shapes/expected_objects.csv' \
                          --status '${PROJECT_SOURCE_DIR}/vectors/labelling/shapes/expected_status.csv' \
                          --image-size 64 48 --focal 60 --baseline 0.3 --max-disp 16 \
                          --config small --out user_warning && \
                          '$<TARGET_FILE:scw>' vectors verify user_warning"
         WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
set_tests_properties("vectors:scw vectors warning from a user's object tables makes a set"
                     PROPERTIES FIXTURES_SETUP scw_user_warning_set)
scw_replay_user_set(user_warning scw_user_warning_set "the warning set from a user's tables replays")
# The field's width is scw_pkg.sv's (AreaBits): the message's is matched, not spelled here.
add_test(NAME "vectors:scw vectors warning refuses a value wider than its field, naming line and column"
         COMMAND bash -c "sed '2s/^0,0,1,1600,/0,0,1,99999999999,/' \
                          '${PROJECT_SOURCE_DIR}/vectors/labelling/shapes/expected_objects.csv' > wide.csv && \
                          '$<TARGET_FILE:scw>' vectors warning --objects wide.csv --out user_wide"
         WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
set_tests_properties("vectors:scw vectors warning refuses a value wider than its field, naming line and column"
                     PROPERTIES PASS_REGULAR_EXPRESSION "wide.csv:2: area '99999999999' does not fit the field's [0-9]+ bits")

# Several frames back to back at a pipeline build: two pairs (the Tsukuba pair and the raw
# chessboard pair, each cropped at 128 96) through the small build's stage at P = 1 (N 9,
# 128 x 96), verified, then replayed.
add_test(NAME "vectors:scw vectors disparity makes a two-frame set at the small build"
         COMMAND bash -c "rm -rf user_disparity_small && '$<TARGET_FILE:scw>' vectors disparity \
                          --config small --ppc 1 \
                          --left '${_tsukuba}/scene1.row3.col3.ppm' '${_chess}/left01.jpg' \
                          --right '${_tsukuba}/scene1.row3.col4.ppm' '${_chess}/right01.jpg' \
                          --roi 128 96 128 96 --out user_disparity_small && \
                          '$<TARGET_FILE:scw>' vectors verify user_disparity_small"
         WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
set_tests_properties("vectors:scw vectors disparity makes a two-frame set at the small build"
                     PROPERTIES FIXTURES_SETUP scw_user_disparity_small_set)
# Verilator only: pipeline/small_street replays this stage at these parameters in Icarus.
scw_replay_user_set(user_disparity_small scw_user_disparity_small_set
                    "the two-frame small-build disparity set replays" SIMULATORS verilator)
add_test(NAME "vectors:scw vectors disparity refuses a window the build is not made with"
         COMMAND $<TARGET_FILE:scw> vectors disparity --config thesis --ppc 1 --window 9
                 --left "${_tsukuba}/scene1.row3.col3.ppm" --right "${_tsukuba}/scene1.row3.col4.ppm"
                 --out user_badwindow
         WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
set_tests_properties("vectors:scw vectors disparity refuses a window the build is not made with"
                     PROPERTIES PASS_REGULAR_EXPRESSION "the thesis build matches with N = 21; give --window 21")

# Two maps back to back at a crop smaller than the build (40 x 30): the Tsukuba pair matched in
# opencv and in thesis mode, labelled, verified and replayed in Icarus.
add_test(NAME "vectors:scw vectors labelling makes a two-frame set from a user's maps"
         COMMAND bash -c "rm -rf user_labelling2 && for m in opencv thesis; do \
                            '$<TARGET_FILE:scw>' disparity --left '${_tsukuba}/scene1.row3.col3.ppm' \
                            --right '${_tsukuba}/scene1.row3.col4.ppm' --window 9 --min-disp 0 \
                            --max-disp 15 --mode $m --out user2_$m.png --out16 user2_16_$m.png \
                            || exit 1; \
                          done && '$<TARGET_FILE:scw>' vectors labelling \
                          --disparity user2_16_opencv.png user2_16_thesis.png \
                          --roi 144 112 40 30 --out user_labelling2 && \
                          '$<TARGET_FILE:scw>' vectors verify user_labelling2"
         WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
set_tests_properties("vectors:scw vectors labelling makes a two-frame set from a user's maps"
                     PROPERTIES FIXTURES_SETUP scw_user_labelling2_set)
scw_replay_user_set(user_labelling2 scw_user_labelling2_set
                    "the two-frame labelling set from a user's maps replays")

# A pipeline set of raw frames and a calibration: three synthetic street frames taken as raw and
# rectified with a made-up 64 x 32 rig's grid maps (tests/vectors/small_rig_64x32.yml), checked
# against the Verilated small top by the generator, verified and replayed.
add_test(NAME "vectors:scw vectors pipeline makes a set of raw frames with a calibration"
         COMMAND bash -c "rm -rf user_pipeline_calib && '$<TARGET_FILE:scw>' vectors pipeline \
                          --config small --frames 3 \
                          --calib '${PROJECT_SOURCE_DIR}/tests/vectors/small_rig_64x32.yml' \
                          --out user_pipeline_calib && \
                          '$<TARGET_FILE:scw>' vectors verify user_pipeline_calib"
         WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
set_tests_properties("vectors:scw vectors pipeline makes a set of raw frames with a calibration"
                     PROPERTIES FIXTURES_SETUP scw_user_pipeline_calib_set)
# Verilator only: pipeline/small_street replays the small top in Icarus.
scw_replay_user_set(user_pipeline_calib scw_user_pipeline_calib_set
                    "the pipeline set of raw frames with a calibration replays"
                    SIMULATORS verilator)
add_test(NAME "vectors:scw vectors pipeline refuses a calibration of another size"
         COMMAND $<TARGET_FILE:scw> vectors pipeline --config small --frames 1
                 --calib "${_chess}/derived_stereo_calibration_helper.yml" --out user_badcalib
         WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
set_tests_properties("vectors:scw vectors pipeline refuses a calibration of another size"
                     PROPERTIES PASS_REGULAR_EXPRESSION "calibrates 640x480 images, the frames are 64x32")

# --sequence reads a folder of numbered pairs in name order: the same pairs given as --left and
# --right make the same set byte for byte (the committed texture pair, then the same swapped).
set(_texture "${PROJECT_SOURCE_DIR}/vectors/disparity/texture")
add_test(NAME "vectors:scw vectors pipeline --sequence equals the same pairs given as --left and --right"
         COMMAND bash -c "rm -rf user_seq user_seq_a user_seq_b && mkdir user_seq && \
                          cp '${_texture}/left.png' user_seq/0000_left.png && \
                          cp '${_texture}/right.png' user_seq/0000_right.png && \
                          cp '${_texture}/right.png' user_seq/0001_left.png && \
                          cp '${_texture}/left.png' user_seq/0001_right.png && \
                          '$<TARGET_FILE:scw>' vectors pipeline --engine cpp --sequence user_seq \
                          --out user_seq_a && \
                          '$<TARGET_FILE:scw>' vectors pipeline --engine cpp \
                          --left '${_texture}/left.png' '${_texture}/right.png' \
                          --right '${_texture}/right.png' '${_texture}/left.png' --out user_seq_b && \
                          for f in user_seq_a/*; do cmp \"$f\" \"user_seq_b/\${f#user_seq_a/}\" || exit 1; done"
         WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})

# Two raw pairs back to back through one rectify stage (the chessboard pair, then the same pair
# swapped), one map: verified and replayed in Icarus.
add_test(NAME "vectors:scw vectors rectify makes a two-frame set from a user's raw pairs"
         COMMAND bash -c "rm -rf user_rectify2 && '$<TARGET_FILE:scw>' vectors rectify \
                          --left '${_chess}/left01.jpg' '${_chess}/right01.jpg' \
                          --right '${_chess}/right01.jpg' '${_chess}/left01.jpg' \
                          --calib '${_chess}/derived_stereo_calibration_helper.yml' \
                          --out user_rectify2 && '$<TARGET_FILE:scw>' vectors verify user_rectify2"
         WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
set_tests_properties("vectors:scw vectors rectify makes a two-frame set from a user's raw pairs"
                     PROPERTIES FIXTURES_SETUP scw_user_rectify2_set)
scw_replay_user_set(user_rectify2 scw_user_rectify2_set
                    "the two-frame rectify set from a user's raw pairs replays")

# A road set from a user's maps at a pipeline build: the committed small_street pair (its three
# frames one under another) matched by scw disparity, its bottom 64 x 32 four times back to back
# through the small build's road stage at P = 1 on a rig of one's own; verified and replayed.
set(_street "${PROJECT_SOURCE_DIR}/vectors/pipeline/small_street")
add_test(NAME "vectors:scw vectors road makes a set from a user's maps at the small build"
         COMMAND bash -c "rm -rf user_road && '$<TARGET_FILE:scw>' disparity \
                          --left '${_street}/left.png' --right '${_street}/right.png' --window 9 \
                          --min-disp 0 --max-disp 15 --out user_road8.png --out16 user_road16.png && \
                          '$<TARGET_FILE:scw>' vectors road --config small --ppc 1 \
                          --disparity user_road16.png user_road16.png user_road16.png user_road16.png \
                          --roi 0 64 64 32 --focal 100 --baseline 0.2 --cy 79.5 --camera-height 1.2 \
                          --out user_road && '$<TARGET_FILE:scw>' vectors verify user_road"
         WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
set_tests_properties("vectors:scw vectors road makes a set from a user's maps at the small build"
                     PROPERTIES FIXTURES_SETUP scw_user_road_set)
scw_replay_user_set(user_road scw_user_road_set "the road set from a user's maps replays")

# --frames K: a preset's one frame sent twice back to back (the stage from reset, then again
# with its state from the first frame), verified and replayed in Icarus.
add_test(NAME "vectors:scw vectors rectify --frames 2 repeats the shift preset"
         COMMAND bash -c "rm -rf frames_shift && '$<TARGET_FILE:scw>' vectors rectify \
                          --preset shift --frames 2 --out frames_shift && \
                          '$<TARGET_FILE:scw>' vectors verify frames_shift"
         WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
set_tests_properties("vectors:scw vectors rectify --frames 2 repeats the shift preset"
                     PROPERTIES FIXTURES_SETUP scw_frames_shift_set)
scw_replay_user_set(frames_shift scw_frames_shift_set "the shift preset twice replays")
