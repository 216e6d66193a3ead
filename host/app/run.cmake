# SPDX-License-Identifier: Apache-2.0
# The whole chain on stereo pairs (scw run): stages' C++ models plus the application layer.
target_sources(scw_host PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/app/run.cpp)
target_sources(scw_host PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/app/group.cpp)
# What `scw run` reads and writes around the chain: the pairs, the camera, the frame's files.
target_sources(scw_host PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/app/pair_files.cpp
                                ${CMAKE_CURRENT_SOURCE_DIR}/app/sequence.cpp
                                ${CMAKE_CURRENT_SOURCE_DIR}/app/camera.cpp
                                ${CMAKE_CURRENT_SOURCE_DIR}/app/frame_files.cpp)
# Splitting a run over processes or machines (--shard I/N) and joining the shards (scw merge).
target_sources(scw_host PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/app/shard.cpp
                                ${CMAKE_CURRENT_SOURCE_DIR}/app/shard_merge.cpp)
