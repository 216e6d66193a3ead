# SPDX-License-Identifier: Apache-2.0
# scw_pipeline_build(): one pipeline build, every block Verilated at one row of
# hls/pipeline/pipeline_configs.def, the row the C++ type `<CONFIG>Pipeline<P>` is made from.
#
#   scw_pipeline_build(<library> CONFIG <Name> PREFIX <p> BLOCK_PPC <P>... LANE_PPC <P>...
#                      [TOP_PPC <P>...])
#
# Models go into <library> (made here, scw_rtl_model_library()), named V<p>_p<P>_<block>:
#   BLOCK_PPC  the widths of the blocks whose beat width only widens their datapath (frame check,
#              map-grid expander, rectifier, disparity);
#   LANE_PPC   the widths of the blocks whose structure changes with it (the labelling stage's
#              lanes, the road stage's histogram ports);
#   TOP_PPC    the widths of the scw_pipeline top;
# and once, with no width: the warning stage (V<p>_warning), ground removal (V<p>_ground) and
# the result merge (V<p>_merge). <library> gets SCW_<NAME>_RTL_P<P>=1 for every BLOCK_PPC width,
# so C++ can tell which widths were built. The C++ bundles in sim/builds/ static_assert every
# model's parameters against the same row, so a hand edit of either side fails the build.

# The row <Name> of pipeline_configs.def as variables cfg_<Parameter> in the caller's scope.
function(scw_pipeline_config name)
  set(def "${PROJECT_SOURCE_DIR}/hls/pipeline/pipeline_configs.def")
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${def}")
  file(STRINGS "${def}" rows REGEX "^SCW_PIPELINE_CONFIG\\(")
  set(columns MaxWidthPx MaxHeight RectRows GridLog2 Window NumDisp MaxTilesX MaxTilesY
              LabelsPerTile MaxObjects MaxDisparityPx)
  foreach(row IN LISTS rows)
    string(REGEX REPLACE "[ \t]" "" row "${row}")
    string(REGEX MATCH "^SCW_PIPELINE_CONFIG\\(([A-Za-z0-9_]+),([0-9,]+)\\)$" whole "${row}")
    if(NOT whole)
      message(FATAL_ERROR "${def}: cannot read the row '${row}' (Name, then numbers)")
    endif()
    if(NOT CMAKE_MATCH_1 STREQUAL name)
      continue()
    endif()
    string(REPLACE "," ";" values "${CMAKE_MATCH_2}")
    list(LENGTH values n)
    list(LENGTH columns want)
    if(NOT n EQUAL want)
      message(FATAL_ERROR "${def}: row ${name} has ${n} numbers, the columns are ${want}")
    endif()
    foreach(col value IN ZIP_LISTS columns values)
      set(cfg_${col} ${value} PARENT_SCOPE)
    endforeach()
    return()
  endforeach()
  message(FATAL_ERROR "${def} has no row '${name}'")
endfunction()

function(scw_pipeline_build lib)
  cmake_parse_arguments(ARG "TRACE_TOP" "CONFIG;PREFIX" "BLOCK_PPC;LANE_PPC;TOP_PPC" ${ARGN})
  # Only a top built with TRACE_TOP can write an FST (scw soak's trace around a divergence);
  # tracing costs every block compile time, so the rest are built without.
  set(top_trace NO_TRACE)
  if(ARG_TRACE_TOP)
    set(top_trace "")
  endif()
  scw_pipeline_config(${ARG_CONFIG})
  set(frame MaxWidthPx=${cfg_MaxWidthPx} MaxHeight=${cfg_MaxHeight})
  set(tiles MaxTilesX=${cfg_MaxTilesX} MaxTilesY=${cfg_MaxTilesY}
            LabelsPerTile=${cfg_LabelsPerTile} MaxObjects=${cfg_MaxObjects})
  set(v "V${ARG_PREFIX}")
  string(TOUPPER "${ARG_CONFIG}" upper)
  scw_rtl_model_library(${lib})
  foreach(p IN LISTS ARG_BLOCK_PPC)
    scw_verilate(${lib} TOP scw_frame_check PREFIX ${v}_p${p}_check STAGE pipeline
                 FILES scw_frame_check.sv PARAMS Ppc=${p} ${frame} NO_TRACE)
    scw_verilate(${lib} TOP scw_rectify_map_grid PREFIX ${v}_p${p}_grid STAGE rectify
                 PARAMS Ppc=${p} ${frame} GridLog2=${cfg_GridLog2} NO_TRACE)
    scw_verilate(${lib} TOP scw_rectify PREFIX ${v}_p${p}_rectify STAGE rectify
                 PARAMS Ppc=${p} ${frame} Rows=${cfg_RectRows} NO_TRACE)
    scw_verilate(${lib} TOP scw_disparity PREFIX ${v}_p${p}_disparity STAGE disparity
                 PARAMS Ppc=${p} ${frame} Window=${cfg_Window} NumDisp=${cfg_NumDisp} NO_TRACE)
    target_compile_definitions(${lib} INTERFACE SCW_${upper}_RTL_P${p}=1)
  endforeach()
  foreach(p IN LISTS ARG_LANE_PPC)
    scw_verilate(${lib} TOP scw_labelling PREFIX ${v}_p${p}_labelling STAGE labelling
                 PARAMS ${frame} ${tiles} Lanes=${p} NO_TRACE)
    scw_verilate(${lib} TOP scw_road PREFIX ${v}_p${p}_road STAGE road
                 PARAMS Ppc=${p} ${frame} NO_TRACE)
  endforeach()
  foreach(p IN LISTS ARG_TOP_PPC)
    scw_verilate(${lib} TOP scw_pipeline PREFIX ${v}_p${p}_top
                 STAGE rectify disparity road labelling warning pipeline
                 PARAMS Ppc=${p} ${frame} RectRows=${cfg_RectRows} GridLog2=${cfg_GridLog2}
                        Window=${cfg_Window} NumDisp=${cfg_NumDisp} ${tiles}
                        MaxDisparityPx=${cfg_MaxDisparityPx} ${top_trace})
  endforeach()
  scw_verilate(${lib} TOP scw_warning PREFIX ${v}_warning STAGE warning
               PARAMS MaxDisparityPx=${cfg_MaxDisparityPx} NO_TRACE)
  scw_verilate(${lib} TOP scw_ground PREFIX ${v}_ground STAGE ground
               PARAMS MaxWidthPx=${cfg_MaxWidthPx} NO_TRACE)
  scw_verilate(${lib} TOP scw_result_merge PREFIX ${v}_merge STAGE pipeline
               FILES scw_result_merge.sv NO_TRACE)
endfunction()
