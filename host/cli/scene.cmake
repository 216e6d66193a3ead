# SPDX-License-Identifier: Apache-2.0
# `scw scene`: synthetic stereo street scenes with ground truth (docs/scene.md).
target_sources(scw PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/cmd_scene.cpp)
