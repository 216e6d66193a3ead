# SPDX-License-Identifier: Apache-2.0
# Every committed golden vector set replays against its RTL block in both simulators through the
# one entry point a user runs (scripts/replay.sh; docs/vectors.md, "Replaying a set"): the
# SystemVerilog in Verilator (2-state), and the block as Yosys writes it in Icarus Verilog
# (4-state), each with idle input cycles and output backpressure. A new set under vectors/ is
# replayed by adding its folder; nothing here names a set.
# Every replay shares one cache in the build (scripts/replay.sh, SCW_REPLAY_CACHE): Verilator's
# runtime objects compiled by the first replay, and each testbench or Yosys-written block built
# once for every set (or the wrong-beat copy) that needs the same one.
set(SCW_REPLAY_ENV "SCW_REPLAY_CACHE=${CMAKE_BINARY_DIR}/replay-cache")
file(GLOB _scw_set_manifests CONFIGURE_DEPENDS "${PROJECT_SOURCE_DIR}/vectors/*/*/manifest.json")
list(SORT _scw_set_manifests)
foreach(_manifest IN LISTS _scw_set_manifests)
  get_filename_component(_set_dir "${_manifest}" DIRECTORY)
  file(RELATIVE_PATH _set "${PROJECT_SOURCE_DIR}/vectors" "${_set_dir}")
  string(REPLACE "/" "_" _work "${_set}")
  foreach(_sim verilator icarus)
    set(_name "vectors:${_set} replays in ${_sim}")
    add_test(NAME "${_name}"
             COMMAND bash "${PROJECT_SOURCE_DIR}/scripts/replay.sh" "${_set_dir}"
                     "replay/${_sim}/${_work}" --simulator ${_sim}
             WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
    set_tests_properties("${_name}" PROPERTIES LABELS "vectors;${_sim}" TIMEOUT 300
                                               ENVIRONMENT "${SCW_REPLAY_ENV}")
  endforeach()
endforeach()

# A wrong expected beat in the committed pipeline set must stop both simulators, naming the
# stream, frame, row and column (tests/pipeline/tb/wrong_beat.sh changes one disparity beat).
add_test(NAME "vectors:a wrong beat in pipeline/small_street fails both simulators, named by stream, frame, row and column"
         COMMAND bash "${PROJECT_SOURCE_DIR}/tests/pipeline/tb/wrong_beat.sh"
                 "${PROJECT_SOURCE_DIR}/vectors/pipeline/small_street" wrong_beat
         WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
set_tests_properties("vectors:a wrong beat in pipeline/small_street fails both simulators, named by stream, frame, row and column"
                     PROPERTIES LABELS "vectors;verilator;icarus" TIMEOUT 300
                                ENVIRONMENT "${SCW_REPLAY_ENV}")
