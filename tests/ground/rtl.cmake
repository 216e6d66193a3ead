# SPDX-License-Identifier: Apache-2.0
# [rtl] scw_ground against the ground-removal model clock for clock, at the two builds of
# ground/test_ground_rtl.cpp (which static_asserts the same parameters); and the stage's window
# in block RAM at 1280 pixels (rtl.yosys.ground_bram).
scw_rtl_model_library(scw_test_rtl_ground)
scw_verilate(scw_test_rtl_ground TOP scw_ground PREFIX Vground_w32 STAGE ground
             PARAMS MaxWidthPx=32)
scw_verilate(scw_test_rtl_ground TOP scw_ground PREFIX Vground_w20 STAGE ground
             PARAMS MaxWidthPx=20)
# Its line buffer alone (16-bit disparities as two lanes, the RAM's output registered), so every
# window is compared, not only the decisions it leads to.
scw_verilate(scw_test_rtl_ground TOP scw_line_buffer PREFIX Vground_lb
             PARAMS Ppc=2 MaxWidthPx=64 Rows=11 RdReg=1)
add_executable(test_ground_rtl ground/test_ground_rtl.cpp)
target_link_libraries(test_ground_rtl PRIVATE scw_test_main scw::sim scw::host scw_test_rtl_ground)
target_compile_definitions(test_ground_rtl PRIVATE SCW_DATA_DIR="${PROJECT_SOURCE_DIR}/data")
scw_warnings(test_ground_rtl)
scw_discover_tests(test_ground_rtl TEST_PREFIX "ground:")

# 10 rows x 1280 columns x 16 bits (204,800 bits) must be block RAM, not flip-flops or LUT RAM.
# The limit leaves room for the line buffer's window, RAM output, forwarding and output
# registers (about 800 FFs; docs/ground.md).
# rtl_models/CMakeLists.txt found Yosys (SCW_YOSYS_EXECUTABLE); without it the test runs and
# fails saying so, like every rtl.yosys.* test (`ctest -LE yosys` skips them on purpose).
set(_scw_ground_synth_env)
if(SCW_YOSYS_EXECUTABLE)
  set(_scw_ground_synth_env "YOSYS=${SCW_YOSYS_EXECUTABLE}")
endif()
add_test(NAME rtl.yosys.ground_bram
         COMMAND bash "${PROJECT_SOURCE_DIR}/scripts/rtl_synth.sh" scw_ground MaxWidthPx=1280
                 --expect-bram --max-ff 1000
                 --log "${CMAKE_CURRENT_BINARY_DIR}/yosys/ground_bram.log")
set_tests_properties(rtl.yosys.ground_bram PROPERTIES LABELS "rtl;yosys" TIMEOUT 300 COST 20
                     ENVIRONMENT "${_scw_ground_synth_env}")
