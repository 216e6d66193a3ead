# SPDX-License-Identifier: Apache-2.0
# `scw segment`: labels a disparity map with the labelling stage's model.
target_sources(scw PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/cmd_segment.cpp)
