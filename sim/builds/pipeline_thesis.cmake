# SPDX-License-Identifier: Apache-2.0
# The thesis-size pipeline build (hls::pipeline::ThesisPipeline<P>: 1280 x 480, window 21, 45
# candidates; sim/builds/pipeline_thesis_rtl.hpp static_asserts these parameters): every block
# Verilated at each beat width of SCW_THESIS_RTL_PPC (1, 2, 4), for `scw sim --config thesis
# --engine rtl`. Many minutes of Verilator and g++ -O3 per width, so only with
# -DSCW_THESIS_RTL=ON (docs/performance.md), never in CI.
set(SCW_THESIS_RTL_PPC "1;2" CACHE STRING "Beat widths of the thesis-size Verilated blocks")
scw_rtl_model_library(scw_rtl_pipeline_thesis)
foreach(p IN LISTS SCW_THESIS_RTL_PPC)
  scw_verilate(scw_rtl_pipeline_thesis TOP scw_frame_check PREFIX Vthesis_p${p}_check
               STAGE pipeline FILES scw_frame_check.sv PARAMS Ppc=${p} MaxWidthPx=1280 MaxHeight=480 NO_TRACE)
  scw_verilate(scw_rtl_pipeline_thesis TOP scw_rectify_map_grid PREFIX Vthesis_p${p}_grid
               STAGE rectify PARAMS Ppc=${p} MaxWidthPx=1280 MaxHeight=480 GridLog2=4 NO_TRACE)
  scw_verilate(scw_rtl_pipeline_thesis TOP scw_rectify PREFIX Vthesis_p${p}_rectify STAGE rectify
               PARAMS Ppc=${p} MaxWidthPx=1280 MaxHeight=480 Rows=64 NO_TRACE)
  scw_verilate(scw_rtl_pipeline_thesis TOP scw_disparity PREFIX Vthesis_p${p}_disparity
               STAGE disparity
               PARAMS Ppc=${p} MaxWidthPx=1280 MaxHeight=480 Window=21 NumDisp=45 NO_TRACE)
  scw_verilate(scw_rtl_pipeline_thesis TOP scw_labelling PREFIX Vthesis_p${p}_labelling
               STAGE labelling
               PARAMS MaxWidthPx=1280 MaxHeight=480 MaxTilesX=8 MaxTilesY=4 LabelsPerTile=32
                      MaxObjects=256 Lanes=${p} NO_TRACE)
  scw_verilate(scw_rtl_pipeline_thesis TOP scw_road PREFIX Vthesis_p${p}_road STAGE road
               PARAMS Ppc=${p} MaxWidthPx=1280 MaxHeight=480 NO_TRACE)
  if(NOT p EQUAL 1)
    target_compile_definitions(scw_rtl_pipeline_thesis INTERFACE SCW_THESIS_RTL_P${p}=1)
  endif()
endforeach()
scw_verilate(scw_rtl_pipeline_thesis TOP scw_warning PREFIX Vthesis_warning STAGE warning
             PARAMS MaxDisparityPx=128 NO_TRACE)
scw_verilate(scw_rtl_pipeline_thesis TOP scw_ground PREFIX Vthesis_ground STAGE ground
             PARAMS MaxWidthPx=1280 NO_TRACE)
scw_verilate(scw_rtl_pipeline_thesis TOP scw_result_merge PREFIX Vthesis_merge STAGE pipeline
             FILES scw_result_merge.sv NO_TRACE)
