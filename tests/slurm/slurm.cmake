# SPDX-License-Identifier: Apache-2.0
# [slurm] A sharded scw run through a one-node Slurm cluster the test starts and stops itself
# (root, Debian's slurm-wlm and munge: scripts/deps.sh; docs/slurm.md). It shares the machine with
# the other tests: its jobs only run slower then, and the cluster's ports are its own (16817 and
# 16818). Run alone at the end (RUN_SERIAL), it left a core idle for its 24 s.
add_test(NAME "slurm:a 4-shard job array merged equals one process byte for byte"
         COMMAND bash "${CMAKE_CURRENT_SOURCE_DIR}/slurm/sharded_run.sh" "$<TARGET_FILE:scw>"
                 "${CMAKE_CURRENT_BINARY_DIR}/slurm_sharded_run")
set_tests_properties("slurm:a 4-shard job array merged equals one process byte for byte"
                     PROPERTIES LABELS slurm TIMEOUT 900 COST 30)
