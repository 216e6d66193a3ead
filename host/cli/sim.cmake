# SPDX-License-Identifier: Apache-2.0
# `scw sim`: the whole pipeline clocked (the small build's Verilated blocks always; the thesis
# size's with -DSCW_THESIS_RTL=ON, scw_pipeline_build in sim/CMakeLists.txt).
target_sources(scw PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/cmd_sim.cpp)
target_link_libraries(scw PRIVATE scw_rtl_engine)
if(SCW_THESIS_RTL)
  target_compile_definitions(scw PRIVATE SCW_THESIS_RTL=1)
endif()

# `scw soak`: the small build's top against the C++ chain, long runs and resets (host/soak/).
target_sources(scw PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/cmd_soak.cpp)
target_link_libraries(scw PRIVATE scw_soak)
