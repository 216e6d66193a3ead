# SPDX-License-Identifier: Apache-2.0
# The labelling stage's whole-frame post-processing (thesis 3.2) and its pictures.
target_sources(scw_host PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/labelling/postprocess.cpp
                                ${CMAKE_CURRENT_SOURCE_DIR}/labelling/picture.cpp)
