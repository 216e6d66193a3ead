# SPDX-License-Identifier: Apache-2.0
# [rtl] scw_road against sim::RoadModel clock for clock at the three builds of
# road/test_road_rtl.cpp (which static_asserts the same parameters), and its fit engine alone
# against fit_line() and band().
scw_rtl_model_library(scw_test_rtl_road)
scw_verilate(scw_test_rtl_road TOP scw_road PREFIX Vroad_p1 STAGE road
             PARAMS Ppc=1 MaxWidthPx=32 MaxHeight=24)
scw_verilate(scw_test_rtl_road TOP scw_road PREFIX Vroad_p2 STAGE road
             PARAMS Ppc=2 MaxWidthPx=32 MaxHeight=24)
scw_verilate(scw_test_rtl_road TOP scw_road PREFIX Vroad_p4 STAGE road
             PARAMS Ppc=4 MaxWidthPx=64 MaxHeight=20)
scw_verilate(scw_test_rtl_road TOP scw_road_fit PREFIX Vroad_fit STAGE road
             FILES scw_road_fit.sv scw_road_mul.sv scw_road_sub.sv scw_road_div.sv)
add_executable(test_road_rtl road/test_road_rtl.cpp)
target_link_libraries(test_road_rtl PRIVATE scw_test_main scw::sim scw::host scw_test_rtl_road)
scw_warnings(test_road_rtl)
scw_discover_tests(test_road_rtl TEST_PREFIX "road:")

# The thesis-size stage closes the timing rule of docs/timing.md (every register-to-register path
# at most 3,500 ps in Yosys sta) at 1 and 4 disparities a beat. A benchmark, like every other
# thesis-size run: registered but disabled unless -DSCW_SYNTH_THESIS=ON (CI's guard is
# rtl.yosys.scw_road at the stage's small defaults). Without Yosys the tests fail saying so,
# like every rtl.yosys.* test (`ctest -LE yosys` skips them).
set(_scw_road_synth_env)
if(SCW_YOSYS_EXECUTABLE)
  set(_scw_road_synth_env "YOSYS=${SCW_YOSYS_EXECUTABLE}")
endif()
foreach(p 1 4)
  add_test(NAME rtl.yosys.road_sta_p${p}
           COMMAND bash "${PROJECT_SOURCE_DIR}/scripts/rtl_synth.sh" scw_road Ppc=${p}
                   MaxWidthPx=1280 MaxHeight=480 --no-ltp --max-sta-ps 3500
                   --log "${CMAKE_CURRENT_BINARY_DIR}/yosys/road_sta_p${p}.log")
  set_tests_properties(rtl.yosys.road_sta_p${p} PROPERTIES LABELS "rtl;yosys" TIMEOUT 300 COST 20
                       ENVIRONMENT "${_scw_road_synth_env}")
  if(NOT SCW_SYNTH_THESIS)
    set_tests_properties(rtl.yosys.road_sta_p${p} PROPERTIES DISABLED ON)
  endif()
endforeach()
