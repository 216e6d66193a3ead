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
                                  ${CMAKE_CURRENT_SOURCE_DIR}/pipeline/sim_split.cpp
                                  ${CMAKE_CURRENT_SOURCE_DIR}/pipeline/sim_text.cpp
                                  ${CMAKE_CURRENT_SOURCE_DIR}/vectors/pipeline_set.cpp)
target_link_libraries(scw_rtl_engine PUBLIC scw::host scw_rtl_pipeline_small)
if(SCW_THESIS_RTL)
  target_link_libraries(scw_rtl_engine PUBLIC scw_rtl_pipeline_thesis)
  target_compile_definitions(scw_rtl_engine PUBLIC SCW_THESIS_RTL=1)
else()
  # Without the thesis build it drives only the small build's models (-O1 too: sim/CMakeLists.txt)
  # for a few frames, in the tests and `scw sim --config small`: -O1 compiles its one unity file
  # in two thirds of the time. The thesis build's chain runs long (docs/performance.md) and keeps
  # -O3.
  target_compile_options(scw_rtl_engine PRIVATE ${SCW_QUICK_OPT})
endif()
scw_warnings(scw_rtl_engine)
