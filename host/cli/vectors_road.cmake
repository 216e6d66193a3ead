# SPDX-License-Identifier: Apache-2.0
# `scw vectors road`: golden vector sets of the road stage, from its C++ model (the generator,
# host/vectors/road_set.cpp, is in the host library: host/road/road.cmake).
target_sources(scw PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/cmd_vectors_road.cpp)
