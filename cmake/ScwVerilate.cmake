# SPDX-License-Identifier: Apache-2.0
# scw_verilate(): one Verilated model of one RTL module at one parameter set.
#
#   scw_verilate(<target> TOP <module> PREFIX <Vname> [STAGE <dir> ...] [FILES <name.sv> ...]
#                [PARAMS Name=Value ...] [NO_TRACE])
#
# Reads the package, every primitive in rtl_models/common and, with STAGE, rtl_models/<dir>
# for each dir named (a top reads several; with FILES only the named files of the one STAGE:
# a unit test of one block needs no more).
# The C++ side declares the same parameter values once in a constexpr struct and
# static_asserts them against the model's /*verilator public*/ parameters, so a mismatch
# between this call and the C++ fails the build rather than the test. NO_TRACE leaves out the
# FST tracing code (the largest generated files): for whole-pipeline builds whose compile time
# matters more than waveforms (sim::Harness then ignores SCW_FST_DIR for them).
# Unreset registers and explicit Xs are Verilated as `unique`: 0 unless the run sets
# SCW_VERILATOR_SEED (sim/rtl/verilated_harness.hpp), then random from that seed, so every test can
# be rerun with them randomised without another build (docs/rtl.md, "X and reset").
# The installed package (scwConfig.cmake) points it at the installed RTL first.
if(NOT SCW_RTL_DIR)
  set(SCW_RTL_DIR "${CMAKE_CURRENT_LIST_DIR}/../rtl_models")
endif()

function(scw_verilate target)
  cmake_parse_arguments(ARG "NO_TRACE" "TOP;PREFIX" "STAGE;PARAMS;FILES" ${ARGN})
  file(GLOB common_sv CONFIGURE_DEPENDS "${SCW_RTL_DIR}/common/*.sv")
  list(REMOVE_ITEM common_sv "${SCW_RTL_DIR}/common/scw_pkg.sv")
  set(sources "${SCW_RTL_DIR}/common/scw_pkg.sv" ${common_sv})
  if(ARG_STAGE AND ARG_FILES)
    foreach(f IN LISTS ARG_FILES)
      list(APPEND sources "${SCW_RTL_DIR}/${ARG_STAGE}/${f}")
    endforeach()
  elseif(ARG_STAGE)
    foreach(dir IN LISTS ARG_STAGE)
      file(GLOB stage_sv CONFIGURE_DEPENDS "${SCW_RTL_DIR}/${dir}/*.sv")
      list(APPEND sources ${stage_sv})
    endforeach()
  endif()
  set(gargs "")
  foreach(p IN LISTS ARG_PARAMS)
    list(APPEND gargs "-G${p}")
  endforeach()
  set(trace TRACE_FST)
  if(ARG_NO_TRACE)
    set(trace "")
  endif()
  # Marks a target that holds Verilated models, for scw_discover_tests' X-randomised run.
  set_property(TARGET ${target} PROPERTY SCW_VERILATED ON)
  verilate(${target}
    TOP_MODULE ${ARG_TOP}
    PREFIX ${ARG_PREFIX}
    SOURCES ${sources}
    ${trace}
    VERILATOR_ARGS ${gargs} -O3 -Wno-fatal --x-assign unique --x-initial unique)
  scw_verilated_unity(${target} ${ARG_PREFIX})
  scw_verilated_runtime_shared(${target})
endfunction()

# scw_verilated_runtime_shared(<target>): verilate() adds Verilator's runtime (verilated.cpp,
# the threads, DPI and FST files) to every target it is called on, so each model library
# compiled its own copy: 13 copies, 199 s of compile of 1,469 in a fresh build. The runtime
# does not depend on the model or on VM_TRACE (verilated.h only sets WAVES from it), so the
# target drops its copy and links the one library, built once.
function(scw_verilated_runtime_shared target)
  if(NOT TARGET scw_verilated_runtime)
    set(inc "${VERILATOR_ROOT}/include")
    add_library(scw_verilated_runtime STATIC
      "${inc}/verilated.cpp" "${inc}/verilated_dpi.cpp" "${inc}/verilated_fst_c.cpp"
      "${inc}/verilated_threads.cpp")
    target_include_directories(scw_verilated_runtime SYSTEM PUBLIC "${inc}" "${inc}/vltstd")
    target_compile_definitions(scw_verilated_runtime PRIVATE
      VM_COVERAGE=0 VM_SC=0 VM_TRACE=1 VM_TRACE_VCD=0 VM_TRACE_FST=1)
    target_compile_features(scw_verilated_runtime PRIVATE cxx_std_11)
    target_link_libraries(scw_verilated_runtime PUBLIC Threads::Threads z)  # z: FST, as Verilator links it
  endif()
  get_target_property(sources ${target} SOURCES)
  list(FILTER sources EXCLUDE REGEX "^${VERILATOR_ROOT}/include/[^/]+\\.cpp$")
  set_property(TARGET ${target} PROPERTY SOURCES ${sources})
  target_link_libraries(${target} PUBLIC scw_verilated_runtime)
endfunction()

# scw_verilated_unity(<target> <prefix>): compiles one model's generated C++ as one translation
# unit. Verilator writes a file per module class (about 160 for the small pipeline top), each
# parsing the same Verilator headers: compiled one by one they took 146 s for that top, as one
# unit 14 s (docs/performance.md, "Build time"). Verilator's own makefile does the same
# (VM_PARALLEL_BUILDS=0, one __ALL.cpp), so the files are written to be combined; one group per
# model keeps two models' files apart and lets models build in parallel.
function(scw_verilated_unity target prefix)
  get_target_property(binary_dir ${target} BINARY_DIR)
  set(vdir "${binary_dir}/CMakeFiles/${target}.dir/${prefix}.dir/")
  get_target_property(sources ${target} SOURCES)
  set(generated "")
  foreach(s IN LISTS sources)
    string(FIND "${s}" "${vdir}" at)
    if(at EQUAL 0 AND s MATCHES "\\.cpp$")
      list(APPEND generated "${s}")
    endif()
  endforeach()
  if(NOT generated)
    message(FATAL_ERROR "scw_verilated_unity: no generated C++ for ${prefix} under ${vdir}")
  endif()
  set_source_files_properties(${generated} TARGET_DIRECTORY ${target}
                              PROPERTIES UNITY_GROUP ${prefix})
  set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_MODE GROUP)
endfunction()

# scw_rtl_model_library(<name>): a static library to scw_verilate() models into. Its Verilator
# and generated headers are SYSTEM for its users, so their warnings do not drown ours.
function(scw_rtl_model_library name)
  add_library(${name} STATIC)
  target_link_libraries(${name} PUBLIC Threads::Threads)
  set_target_properties(${name} PROPERTIES
    INTERFACE_SYSTEM_INCLUDE_DIRECTORIES $<TARGET_PROPERTY:${name},INTERFACE_INCLUDE_DIRECTORIES>)
endfunction()
