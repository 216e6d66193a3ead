# SPDX-License-Identifier: Apache-2.0
# `scw sim --engine rtl-top` against `--engine rtl` on the same run: every field of the two JSON
# reports equal (cycles, period, latencies, each frame's input and result cycles, the results),
# but for the engine's name and what only the chain of blocks can see (its blocks' busy spans
# and FIFOs), which the top must leave empty.
#   cmake -DSCW=<scw> -DPPC=<P> -DSTALLS=<pattern> [-DCONFIG=small] -P sim_engines_agree.cmake
# runs both on 3 frames of the synthetic street;
#   cmake -DRTL_JSON=<file> -DTOP_JSON=<file> -P sim_engines_agree.cmake
# compares two reports already written (bench/sim_speed.sh; RTL_JSON may be any chain's report).
if(DEFINED RTL_JSON AND DEFINED TOP_JSON)
  file(READ "${RTL_JSON}" json_rtl)
  file(READ "${TOP_JSON}" json_rtl-top)
else()
  foreach(v SCW PPC STALLS)
    if(NOT DEFINED ${v})
      message(FATAL_ERROR "sim_engines_agree.cmake: -D${v}=... is required")
    endif()
  endforeach()
  if(NOT DEFINED CONFIG)
    set(CONFIG small)
  endif()
  foreach(engine rtl rtl-top)
    set(out "${CMAKE_CURRENT_BINARY_DIR}/sim_engines_p${PPC}_${engine}.json")
    file(REMOVE "${out}")
    execute_process(COMMAND "${SCW}" sim --config ${CONFIG} --ppc ${PPC} --frames 3
                            --stalls ${STALLS} --engine ${engine} --json "${out}"
                    RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
    if(NOT rc EQUAL 0)
      message(FATAL_ERROR "scw sim --engine ${engine} failed (${rc}): ${err}")
    endif()
    file(READ "${out}" json_${engine})
  endforeach()
endif()
string(JSON chain_stages LENGTH "${json_rtl}" stages)
string(JSON top_stages LENGTH "${json_rtl-top}" stages)
string(JSON top_fifos LENGTH "${json_rtl-top}" fifos)
if(chain_stages EQUAL 0 OR NOT top_stages EQUAL 0 OR NOT top_fifos EQUAL 0)
  message(FATAL_ERROR "stages: the chain ${chain_stages} (must be > 0), the top ${top_stages} "
                      "and its FIFOs ${top_fifos} (must be 0)")
endif()
foreach(engine rtl rtl-top)
  foreach(key engine stages fifos)
    string(JSON json_${engine} REMOVE "${json_${engine}}" ${key})
  endforeach()
endforeach()
if(NOT json_rtl STREQUAL json_rtl-top)
  message(FATAL_ERROR "the top's report differs from the chain's:\n"
                      "chain: ${json_rtl}\ntop: ${json_rtl-top}")
endif()
string(JSON cycles GET "${json_rtl}" cycles)
string(JSON p GET "${json_rtl}" ppc)
message(STATUS "P = ${p}: the top's report is the chain's, ${cycles} cycles")
