# SPDX-License-Identifier: Apache-2.0
# The small pipeline build (hls::pipeline::SmallPipeline<P>, up to 128 x 96; the static_asserts
# in sim/builds/pipeline_small_rtl.hpp check these parameters): every block Verilated at P = 1,
# at P = 2 the blocks that differ only in width are left to the top (the labelling stage's lanes
# are new), and the scw_pipeline top at both. Seconds to simulate, minutes to compile; `scw sim --config
# small --engine rtl` and tests/pipeline use it.
scw_rtl_model_library(scw_rtl_pipeline_small)
scw_verilate(scw_rtl_pipeline_small TOP scw_frame_check PREFIX Vpipe_p1_check STAGE pipeline
             FILES scw_frame_check.sv PARAMS Ppc=1 MaxWidthPx=128 MaxHeight=96 NO_TRACE)
scw_verilate(scw_rtl_pipeline_small TOP scw_rectify_map_grid PREFIX Vpipe_p1_grid STAGE rectify
             PARAMS Ppc=1 MaxWidthPx=128 MaxHeight=96 GridLog2=3 NO_TRACE)
scw_verilate(scw_rtl_pipeline_small TOP scw_rectify PREFIX Vpipe_p1_rectify STAGE rectify
             PARAMS Ppc=1 MaxWidthPx=128 MaxHeight=96 Rows=16 NO_TRACE)
scw_verilate(scw_rtl_pipeline_small TOP scw_disparity PREFIX Vpipe_p1_disparity STAGE disparity
             PARAMS Ppc=1 MaxWidthPx=128 MaxHeight=96 Window=9 NumDisp=16 NO_TRACE)
foreach(p 1 2)
  scw_verilate(scw_rtl_pipeline_small TOP scw_pipeline PREFIX Vpipe_p${p}_top
               STAGE rectify disparity road labelling warning pipeline
               PARAMS Ppc=${p} MaxWidthPx=128 MaxHeight=96 RectRows=16 GridLog2=3 Window=9
                      NumDisp=16 MaxTilesX=4 MaxTilesY=2 LabelsPerTile=256 MaxObjects=64
                      MaxDisparityPx=32 NO_TRACE)
endforeach()
foreach(p 1 2)
  scw_verilate(scw_rtl_pipeline_small TOP scw_labelling PREFIX Vpipe_p${p}_labelling
               STAGE labelling
               PARAMS MaxWidthPx=128 MaxHeight=96 MaxTilesX=4 MaxTilesY=2 LabelsPerTile=256
                      MaxObjects=64 Lanes=${p} NO_TRACE)
endforeach()
foreach(p 1 2)
  scw_verilate(scw_rtl_pipeline_small TOP scw_road PREFIX Vpipe_p${p}_road STAGE road
               PARAMS Ppc=${p} MaxWidthPx=128 MaxHeight=96 NO_TRACE)
endforeach()
scw_verilate(scw_rtl_pipeline_small TOP scw_warning PREFIX Vpipe_warning STAGE warning
             PARAMS MaxDisparityPx=32 NO_TRACE)
scw_verilate(scw_rtl_pipeline_small TOP scw_ground PREFIX Vpipe_ground STAGE ground
             PARAMS MaxWidthPx=128 NO_TRACE)
scw_verilate(scw_rtl_pipeline_small TOP scw_result_merge PREFIX Vpipe_merge STAGE pipeline
             FILES scw_result_merge.sv NO_TRACE)

# These models simulate a few hundred thousand cycles in the tests: -O1 halves their compile time
# and costs little there.
target_compile_options(scw_rtl_pipeline_small PRIVATE -O1)
