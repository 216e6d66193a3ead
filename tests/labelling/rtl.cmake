# SPDX-License-Identifier: Apache-2.0
# [rtl] scw_labelling against the labelling model clock for clock, at the five builds of
# labelling/test_labelling_rtl.cpp (which static_asserts the same parameters).
scw_rtl_model_library(scw_test_rtl_labelling)
set(_scw_labelling_sv scw_labelling.sv scw_labelling_desc_ram.sv scw_labelling_edge_queue.sv
    scw_labelling_lane.sv scw_labelling_merge.sv scw_labelling_merge_unit.sv)
scw_verilate(scw_test_rtl_labelling TOP scw_labelling PREFIX Vlabelling_a STAGE labelling
             FILES ${_scw_labelling_sv}
             PARAMS MaxWidthPx=32 MaxHeight=24 MaxTilesX=4 MaxTilesY=4 LabelsPerTile=128
                    MaxObjects=256)
scw_verilate(scw_test_rtl_labelling TOP scw_labelling PREFIX Vlabelling_b STAGE labelling
             FILES ${_scw_labelling_sv}
             PARAMS MaxWidthPx=24 MaxHeight=16 MaxTilesX=2 MaxTilesY=2 LabelsPerTile=8
                    MaxObjects=5)
scw_verilate(scw_test_rtl_labelling TOP scw_labelling PREFIX Vlabelling_c STAGE labelling
             FILES ${_scw_labelling_sv}
             PARAMS MaxWidthPx=20 MaxHeight=12 MaxTilesX=3 MaxTilesY=3 LabelsPerTile=20
                    MaxObjects=100)
foreach(lanes 2 4)
  scw_verilate(scw_test_rtl_labelling TOP scw_labelling PREFIX Vlabelling_l${lanes} STAGE labelling
               FILES ${_scw_labelling_sv}
               PARAMS MaxWidthPx=32 MaxHeight=24 MaxTilesX=4 MaxTilesY=4 LabelsPerTile=128
                      MaxObjects=256 Lanes=${lanes})
endforeach()
add_executable(test_labelling_rtl labelling/test_labelling_rtl.cpp)
target_link_libraries(test_labelling_rtl
                      PRIVATE scw_test_main scw::sim scw::host scw_test_rtl_labelling)
scw_warnings(test_labelling_rtl)
scw_discover_tests(test_labelling_rtl TEST_PREFIX "labelling:")
