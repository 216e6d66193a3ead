# SPDX-License-Identifier: Apache-2.0
# [soak] Long runs with broken frames and stalls, and resets in mid-frame: the small build's
# Verilated top against the C++ chain and the floating-point reference (host/soak/).
add_executable(test_soak soak/test_soak.cpp)
target_link_libraries(test_soak PRIVATE scw_test_main scw_soak)
target_compile_definitions(test_soak PRIVATE SCW_DATA_DIR="${PROJECT_SOURCE_DIR}/data")
scw_warnings(test_soak)
scw_discover_tests(test_soak TEST_PREFIX "soak:")

# The command end to end: a short soak with every fault and a few resets writes its JSON; a
# divergence injected on purpose is reported with its frame and an FST trace, and fails the run.
add_test(NAME "soak:cli soak writes the summary, a divergence fails it and is traced"
         COMMAND bash -c "cd '${PROJECT_SOURCE_DIR}' && rm -rf '${CMAKE_CURRENT_BINARY_DIR}/cli_soak' && \
                          '$<TARGET_FILE:scw>' soak --frames 12 --malformed-every 3 --resets 3 \
                          --json '${CMAKE_CURRENT_BINARY_DIR}/cli_soak/ok.json' 2> /dev/null && \
                          grep -q '\"passed\": true' '${CMAKE_CURRENT_BINARY_DIR}/cli_soak/ok.json' && \
                          ! '$<TARGET_FILE:scw>' soak --frames 6 --malformed-every 0 \
                          --inject-divergence 4 --fst '${CMAKE_CURRENT_BINARY_DIR}/cli_soak/fst' \
                          > '${CMAKE_CURRENT_BINARY_DIR}/cli_soak.txt' 2> /dev/null && \
                          grep -q 'first divergence: result 4 at cycle' '${CMAKE_CURRENT_BINARY_DIR}/cli_soak.txt' && \
                          test -s '${CMAKE_CURRENT_BINARY_DIR}/cli_soak/fst/pipeline.fst'")
add_test(NAME "soak:cli soak refuses another build and a missing real pair, naming the fix"
         COMMAND bash -c "! '$<TARGET_FILE:scw>' soak --config thesis 2> soak_bad.err && \
                          grep -q 'give --config small' soak_bad.err && \
                          ! '$<TARGET_FILE:scw>' soak --real-left nowhere.png 2> soak_bad2.err && \
                          grep -q 'give --real-left and --real-right' soak_bad2.err"
         WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
