# SPDX-License-Identifier: Apache-2.0
# `scw vectors pipeline`: golden vector sets of the whole top, from the C++ chain and checked
# against the small build's Verilated top (the generator, host/vectors/pipeline_set.cpp, is in
# scw_rtl_engine: host/pipeline/pipeline.cmake).
target_sources(scw PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/cmd_vectors_pipeline.cpp)
