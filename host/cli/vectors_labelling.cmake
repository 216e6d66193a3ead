# SPDX-License-Identifier: Apache-2.0
# `scw vectors labelling`: golden vector sets of the labelling stage, from its C++ model (the
# generator, host/vectors/labelling_set.cpp, is in the host library: host/labelling/model.cmake).
target_sources(scw PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/cmd_vectors_labelling.cpp)
