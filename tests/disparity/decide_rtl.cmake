# SPDX-License-Identifier: Apache-2.0
# scw_disparity_decide against decide<NumDisp>() cycle by cycle, at a small and the full size.
# FILES: the unit needs only its own file, not the rest of the stage's RTL.
scw_rtl_model_library(scw_test_rtl_decide)
scw_verilate(scw_test_rtl_decide TOP scw_disparity_decide PREFIX Vdecide_n8 STAGE disparity
             FILES scw_disparity_decide.sv PARAMS NumDisp=8 SadBits=12 DminBits=8)
scw_verilate(scw_test_rtl_decide TOP scw_disparity_decide PREFIX Vdecide_n45 STAGE disparity
             FILES scw_disparity_decide.sv PARAMS NumDisp=45 SadBits=17 DminBits=8)
add_executable(test_disparity_decide_rtl disparity/test_disparity_decide_rtl.cpp)
target_link_libraries(test_disparity_decide_rtl
                      PRIVATE scw_test_main scw::sim scw::host scw_test_rtl_decide)
scw_warnings(test_disparity_decide_rtl)
scw_discover_tests(test_disparity_decide_rtl TEST_PREFIX "disparity:")
