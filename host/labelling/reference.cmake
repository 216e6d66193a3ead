# SPDX-License-Identifier: Apache-2.0
# Labelling, host side: the independent flood-fill reference and the Hu moments of its objects.
target_sources(scw_host PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/reference/labelling_ref.cpp
                                ${CMAKE_CURRENT_SOURCE_DIR}/labelling/hu_moments.cpp)
