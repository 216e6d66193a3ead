# SPDX-License-Identifier: Apache-2.0
# The whole pipeline's host side: run settings from user options, the floating-point chain.
target_sources(scw_host PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/pipeline/setup.cpp
                                ${CMAKE_CURRENT_SOURCE_DIR}/pipeline/reference_chain.cpp
                                ${CMAKE_CURRENT_SOURCE_DIR}/pipeline/synthetic.cpp)

# The stages as Verilated RTL for `scw run --engine rtl` and `scw sim` (the small build always,
# the thesis build with SCW_THESIS_RTL): a library of its own, so only its users link the models.
# The whole top's golden vector sets (host/vectors/pipeline_set.cpp) are here too: they check the
# Verilated top.
add_library(scw_rtl_engine STATIC ${CMAKE_CURRENT_SOURCE_DIR}/pipeline/rtl_engine.cpp
                                  ${CMAKE_CURRENT_SOURCE_DIR}/pipeline/sim_run.cpp
                                  ${CMAKE_CURRENT_SOURCE_DIR}/vectors/pipeline_set.cpp)
target_link_libraries(scw_rtl_engine PUBLIC scw::host scw_rtl_pipeline_small)
if(SCW_THESIS_RTL)
  target_link_libraries(scw_rtl_engine PUBLIC scw_rtl_pipeline_thesis)
  target_compile_definitions(scw_rtl_engine PUBLIC SCW_THESIS_RTL=1)
endif()
scw_warnings(scw_rtl_engine)
