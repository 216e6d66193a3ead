# SPDX-License-Identifier: Apache-2.0
# The road stage, host side: the configuration from the rig, the kernel over whole maps, the
# floating-point reference and the golden-vector generator.
target_sources(scw_host PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/road/setup.cpp
                                ${CMAKE_CURRENT_SOURCE_DIR}/road/run_model.cpp
                                ${CMAKE_CURRENT_SOURCE_DIR}/reference/road_ref.cpp
                                ${CMAKE_CURRENT_SOURCE_DIR}/vectors/road_set.cpp)
