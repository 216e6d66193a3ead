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
