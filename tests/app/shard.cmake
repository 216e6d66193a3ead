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
# The commands whose output does not split into shards that join into one process's refuse
# --shard with the reason (docs/slurm.md, "What does not split").
add_test(NAME "app:cli sim, soak and vectors refuse --shard and say why"
         COMMAND bash -c "for c in 'sim|whole-run timing' 'soak|Split seeds instead' \
                          'vectors rectify|one stream' 'vectors disparity|one stream' \
                          'vectors labelling|one stream' 'vectors road|one stream' \
                          'vectors warning|one stream' 'vectors pipeline|one stream'; do \
                          if '$<TARGET_FILE:scw>' \${c%|*} --shard 0/2 2> shard_refused.err; then \
                          echo \"\${c%|*} took --shard\"; exit 1; fi; \
                          grep -q -- \"--shard.*\${c#*|}\" shard_refused.err || \
                          { echo \"\${c%|*}:\"; cat shard_refused.err; exit 1; }; done"
         WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
# scw soak --seeds K: the seeds split over 2 shards and merged equal one process's summaries, but
# for the wall-clock seconds each run measures anew.
add_test(NAME "soak:cli soak --seeds 3 in 2 shards merged equals one process but for wall time"
         COMMAND bash "${CMAKE_CURRENT_SOURCE_DIR}/app/shard_soak.sh" "$<TARGET_FILE:scw>"
                 "${CMAKE_CURRENT_BINARY_DIR}/cli_shard_soak" "${PROJECT_SOURCE_DIR}/data/tsukuba")
