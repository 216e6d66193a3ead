# SPDX-License-Identifier: Apache-2.0
# Soak and reset trials (scw soak): the small build's Verilated top against the C++ chain over
# many frames; a library of its own, like scw_rtl_engine, so only its users link the models.
add_library(scw_soak STATIC ${CMAKE_CURRENT_SOURCE_DIR}/soak/soak_frames.cpp
                            ${CMAKE_CURRENT_SOURCE_DIR}/soak/soak.cpp
                            ${CMAKE_CURRENT_SOURCE_DIR}/soak/soak_report.cpp
                            ${CMAKE_CURRENT_SOURCE_DIR}/soak/reset_trials.cpp)
target_link_libraries(scw_soak PUBLIC scw::host scw_rtl_pipeline_small)
scw_warnings(scw_soak)
