# SPDX-License-Identifier: Apache-2.0
# The labelling model run over whole maps (segment()) for the CLI, vectors and real-data checks,
# and the golden-vector generator.
target_sources(scw_host PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/labelling/run_model.cpp
                                ${CMAKE_CURRENT_SOURCE_DIR}/labelling/segment_files.cpp
                                ${CMAKE_CURRENT_SOURCE_DIR}/labelling/second_pass.cpp
                                ${CMAKE_CURRENT_SOURCE_DIR}/vectors/labelling_set.cpp)
