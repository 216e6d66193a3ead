# SPDX-License-Identifier: Apache-2.0
# `scw run`: the whole chain and the application layer.
target_sources(scw PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/cmd_run.cpp
                           ${CMAKE_CURRENT_SOURCE_DIR}/run_options.cpp)
# `scw merge`: joins the shards of a run made with --shard I/N (docs/slurm.md).
target_sources(scw PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/cmd_merge.cpp)
