# SPDX-License-Identifier: Apache-2.0
# scw_disparity_prefilter against hls::disparity::XSobel cycle for cycle, at 1, 2 and 4 pixels
# per beat; FILES keeps the build off the stage's other (unrelated) modules.
scw_rtl_model_library(scw_test_rtl_prefilter)
foreach(p 1 2 4)
  scw_verilate(scw_test_rtl_prefilter TOP scw_disparity_prefilter PREFIX Vprefilter_p${p}
               STAGE disparity FILES scw_disparity_prefilter.sv
               PARAMS Ppc=${p} MaxWidthPx=32 MaxHeight=16)
endforeach()
add_executable(test_disparity_prefilter_rtl disparity/test_disparity_prefilter_rtl.cpp)
target_link_libraries(test_disparity_prefilter_rtl
                      PRIVATE scw_test_main scw::sim scw::host scw_test_rtl_prefilter)
scw_warnings(test_disparity_prefilter_rtl)
scw_discover_tests(test_disparity_prefilter_rtl TEST_PREFIX "disparity:")
