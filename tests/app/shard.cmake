# SPDX-License-Identifier: Apache-2.0
# Sharding (docs/slurm.md): the rule that splits a run, and `scw run --shard I/N` with `scw merge`
# end to end: the merged shards equal one process byte for byte, and the merge refuses shards
# that are not one whole run.
add_executable(test_shard app/test_shard.cpp)
target_link_libraries(test_shard PRIVATE scw_test_main scw::host)
scw_warnings(test_shard)
scw_discover_tests(test_shard TEST_PREFIX "app:")

add_test(NAME "app:cli run in 3 shards merged equals one process byte for byte"
         COMMAND bash "${CMAKE_CURRENT_SOURCE_DIR}/app/shard_run.sh" "$<TARGET_FILE:scw>"
                 "${CMAKE_CURRENT_BINARY_DIR}/cli_shard_run")
# scw soak without --seeds cannot split (docs/slurm.md, "What does not split"): --shard is
# refused with the reason.
add_test(NAME "app:cli soak refuses --shard without --seeds and says why"
         COMMAND bash -c "if '$<TARGET_FILE:scw>' soak --shard 0/2 2> shard_refused.err; then \
                          echo 'soak took --shard'; exit 1; fi; \
                          grep -q -- 'Split seeds instead' shard_refused.err || \
                          { cat shard_refused.err; exit 1; }"
         WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
# scw sim and scw vectors split into segments, each from reset: 2 shards merged equal one process
# with --segments 2 byte for byte.
add_test(NAME "app:cli sim in 2 shards merged equals one process with --segments 2 byte for byte"
         COMMAND bash "${CMAKE_CURRENT_SOURCE_DIR}/app/shard_sim.sh" "$<TARGET_FILE:scw>"
                 "${CMAKE_CURRENT_BINARY_DIR}/cli_shard_sim")
add_test(NAME "app:cli vectors of every stage in 2 shards merged equal one process with --segments 2"
         COMMAND bash "${CMAKE_CURRENT_SOURCE_DIR}/app/shard_vectors.sh" "$<TARGET_FILE:scw>"
                 "${CMAKE_CURRENT_BINARY_DIR}/cli_shard_vectors")
set_tests_properties("app:cli vectors of every stage in 2 shards merged equal one process with --segments 2"
                     PROPERTIES FIXTURES_SETUP scw_sharded_pipeline_set)
# The merged pipeline set's second segment (frames 2 and 3, the road carried from frame 2 on) is a
# whole set from reset: it replays against the Verilated top.
scw_replay_user_set(cli_shard_vectors/merged_pipeline/frames_0002-0003 scw_sharded_pipeline_set
                    "the second segment of a sharded pipeline set replays" SIMULATORS verilator)
# scw soak --seeds K: the seeds split over 2 shards and merged equal one process's summaries, but
# for the wall-clock seconds each run measures anew.
add_test(NAME "soak:cli soak --seeds 3 in 2 shards merged equals one process but for wall time"
         COMMAND bash "${CMAKE_CURRENT_SOURCE_DIR}/app/shard_soak.sh" "$<TARGET_FILE:scw>"
                 "${CMAKE_CURRENT_BINARY_DIR}/cli_shard_soak" "${PROJECT_SOURCE_DIR}/data/tsukuba")
