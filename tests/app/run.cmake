# SPDX-License-Identifier: Apache-2.0
# The whole chain: a synthetic street pair through app::Runner (the box ahead decides, at the
# distance its disparity gives), and `scw run` end to end on Tsukuba, on a sequence, and on
# inputs it must refuse with a message.
add_executable(test_run app/test_run.cpp)
target_link_libraries(test_run PRIVATE scw_test_main scw::host)
scw_warnings(test_run)
scw_discover_tests(test_run TEST_PREFIX "app:")

set(scw_tsu "${PROJECT_SOURCE_DIR}/data/tsukuba")
# Tsukuba's camera is not published with the pair: f 615 px and b 0.1 m are assumed for the demo.
set(scw_tsu_run "--rectified --focal 615 --baseline 0.1 --window 9 --min-disp 0 --max-disp 15 \
                 --min-area 50")
# `scw run`'s last line names the files a frame wrote: exactly those in folder @DIR@ (its output
# in @DIR@.out).
set(scw_run_names_files "diff <(ls @DIR@ | grep -vx results.jsonl) <(sed -n 's/.*a frame.s //p' @DIR@.out \
                         | tr -d ')' | tr ',' '\\n' | tr -d ' ' | sort)")
string(REPLACE "@DIR@" "cli_run" scw_run_all_named "${scw_run_names_files}")
string(REPLACE "@DIR@" "cli_run_$p" scw_run_p_named "${scw_run_names_files}")
add_test(NAME "app:cli run writes every picture and a results line with the required keys"
         COMMAND bash -c "rm -rf cli_run && '$<TARGET_FILE:scw>' run ${scw_tsu_run} \
                          --left '${scw_tsu}/scene1.row3.col3.ppm' \
                          --right '${scw_tsu}/scene1.row3.col4.ppm' --out-dir cli_run \
                          > cli_run.out && ${scw_run_all_named} && \
                          for f in left_rect.png right_rect.png disparity.png disparity16.png \
                          labels.png labels_color.png overlay.png objects.csv results.jsonl; do \
                          test -s cli_run/$f || { echo missing $f; exit 1; }; done && \
                          test $(wc -l < cli_run/results.jsonl) -eq 1 && \
                          test $(od -An -tu1 -j24 -N1 cli_run/disparity16.png) -eq 16 && \
                          for k in frame severity distance_m closest_uv disparity bbox objects \
                          flags; do grep -q \"\\\"$k\\\":\" cli_run/results.jsonl || \
                          { echo missing key $k; exit 1; }; done"
         WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
# --pictures none and overlay: the same results line, objects.csv always, only the pictures
# chosen, each run naming what it wrote.
add_test(NAME "app:cli run --pictures none and overlay write the same results and only the chosen pictures"
         COMMAND bash -c "for p in none overlay; do rm -rf cli_run_$p && '$<TARGET_FILE:scw>' run \
                          ${scw_tsu_run} --left '${scw_tsu}/scene1.row3.col3.ppm' \
                          --right '${scw_tsu}/scene1.row3.col4.ppm' --pictures $p \
                          --out-dir cli_run_$p > cli_run_$p.out || exit 1; \
                          test -s cli_run_$p/objects.csv && ${scw_run_p_named} || exit 1; done && \
                          test $(ls cli_run_none | grep -c png) -eq 0 && \
                          test \"$(ls cli_run_overlay | grep png)\" = overlay.png && \
                          cmp cli_run_none/results.jsonl cli_run_overlay/results.jsonl && \
                          cmp cli_run_none/objects.csv cli_run_overlay/objects.csv"
         WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
add_test(NAME "app:cli run on a sequence writes one line per pair and shows progress"
         COMMAND bash -c "rm -rf cli_seq cli_seq_out && mkdir cli_seq && for i in 0001 0002 0003; \
                          do cp '${scw_tsu}/scene1.row3.col3.ppm' cli_seq/\${i}_left.ppm && \
                          cp '${scw_tsu}/scene1.row3.col4.ppm' cli_seq/\${i}_right.ppm; done && \
                          '$<TARGET_FILE:scw>' run ${scw_tsu_run} --sequence cli_seq \
                          --out-dir cli_seq_out 2> cli_seq.err && \
                          test $(wc -l < cli_seq_out/results.jsonl) -eq 3 && \
                          grep -q '3/3 frames' cli_seq.err && test -s cli_seq_out/0003_overlay.png"
         WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
foreach(bad
    "rectified without focal|--rectified --left '${scw_tsu}/scene1.row3.col3.ppm' --right '${scw_tsu}/scene1.row3.col4.ppm'|needs --focal"
    "a negative baseline|--rectified --focal 615 --baseline -1 --left '${scw_tsu}/scene1.row3.col3.ppm' --right '${scw_tsu}/scene1.row3.col4.ppm'|--baseline -1: the baseline must be a positive number of m"
    "a negative focal length|--rectified --focal -615 --baseline 0.1 --left '${scw_tsu}/scene1.row3.col3.ppm' --right '${scw_tsu}/scene1.row3.col4.ppm'|--focal -615: the focal length must be a positive"
    "an even window|--rectified --focal 615 --baseline 0.1 --window 4 --left '${scw_tsu}/scene1.row3.col3.ppm' --right '${scw_tsu}/scene1.row3.col4.ppm'|--window: 4 is not a window size"
    "a negative camera height|--rectified --focal 615 --baseline 0.1 --camera-height -1 --left '${scw_tsu}/scene1.row3.col3.ppm' --right '${scw_tsu}/scene1.row3.col4.ppm'|--camera-height: -1 is not positive; give a positive number of m"
    "a zero frame period|--rectified --focal 615 --baseline 0.1 --frame-period 0 --left '${scw_tsu}/scene1.row3.col3.ppm' --right '${scw_tsu}/scene1.row3.col4.ppm'|--frame-period: 0 is not positive"
    "a negative principal point|--rectified --focal 615 --baseline 0.1 --cx -100 --left '${scw_tsu}/scene1.row3.col3.ppm' --right '${scw_tsu}/scene1.row3.col4.ppm'|--cx: -100 is negative"
    "a car width that is not a number|--rectified --focal 615 --baseline 0.1 --car-width nan --left '${scw_tsu}/scene1.row3.col3.ppm' --right '${scw_tsu}/scene1.row3.col4.ppm'|--car-width: nan is not a number"
    "sizes differ|--rectified --focal 615 --baseline 0.1 --left '${scw_tsu}/scene1.row3.col3.ppm' --right '${PROJECT_SOURCE_DIR}/data/chessboard/right01.jpg'|differ in size"
    "an empty sequence folder|--rectified --focal 615 --baseline 0.1 --sequence .|holds no pairs"
    "a broken calibration|--calib '${scw_tsu}/scene1.row3.col3.ppm' --left '${scw_tsu}/scene1.row3.col3.ppm' --right '${scw_tsu}/scene1.row3.col4.ppm'|scene1.row3.col3.ppm"
    "no camera at all|--left '${scw_tsu}/scene1.row3.col3.ppm' --right '${scw_tsu}/scene1.row3.col4.ppm'|give --calib")
  string(REPLACE "|" ";" parts "${bad}")
  list(GET parts 0 what)
  list(GET parts 1 args)
  list(GET parts 2 msg)
  # Each case has its own empty folder: ctest -j runs them side by side.
  string(MAKE_C_IDENTIFIER "cli_bad_${what}" dir)
  add_test(NAME "app:cli run refuses ${what} with a message"
           COMMAND bash -c "rm -rf ${dir} && mkdir -p ${dir}/empty && cd ${dir}/empty && \
                            ! '$<TARGET_FILE:scw>' run ${args} --out-dir ../out 2> ../err.txt && \
                            grep -q -- '${msg}' ../err.txt"
           WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
endforeach()
