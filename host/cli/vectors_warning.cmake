# SPDX-License-Identifier: Apache-2.0
# `scw vectors warning`: golden vector sets of the warning stage, from its C++ model (the
# generator, host/vectors/warning_set.cpp, is in the host library: host/warning/model.cmake).
target_sources(scw PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/cmd_vectors_warning.cpp)
