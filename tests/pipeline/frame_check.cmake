# SPDX-License-Identifier: Apache-2.0
# [rtl] scw_frame_check against its C++ cycle model clock for clock, at the builds that
# pipeline/frame_check_configs.hpp declares (and static_asserts) once.
scw_rtl_model_library(scw_test_rtl_frame_check)
foreach(p 1 2)
  scw_verilate(scw_test_rtl_frame_check TOP scw_frame_check PREFIX Vframe_check_p${p}
               STAGE pipeline FILES scw_frame_check.sv PARAMS Ppc=${p} MaxWidthPx=16 MaxHeight=8)
endforeach()
add_executable(test_pipeline_frame_check pipeline/test_frame_check_rtl.cpp)
target_link_libraries(test_pipeline_frame_check PRIVATE scw_test_main scw::sim
                      scw_test_rtl_frame_check)
scw_warnings(test_pipeline_frame_check)
scw_discover_tests(test_pipeline_frame_check TEST_PREFIX "pipeline:")
