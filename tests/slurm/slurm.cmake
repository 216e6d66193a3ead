# SPDX-License-Identifier: Apache-2.0
# [slurm] A sharded scw run through a one-node Slurm cluster the test starts and stops itself
# (root, Debian's slurm-wlm and munge: scripts/deps.sh; docs/slurm.md). RUN_SERIAL: the cluster's
# ports and the jobs' two cores are the test's alone.
add_test(NAME "slurm:a 4-shard job array merged equals one process byte for byte"
         COMMAND bash "${CMAKE_CURRENT_SOURCE_DIR}/slurm/sharded_run.sh" "$<TARGET_FILE:scw>"
                 "${CMAKE_CURRENT_BINARY_DIR}/slurm_sharded_run")
set_tests_properties("slurm:a 4-shard job array merged equals one process byte for byte"
                     PROPERTIES LABELS slurm RUN_SERIAL TRUE TIMEOUT 900)
