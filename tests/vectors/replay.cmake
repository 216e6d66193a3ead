# SPDX-License-Identifier: Apache-2.0
# Every committed golden vector set replays against its RTL block in both simulators through the
# one entry point a user runs (scripts/replay.sh; docs/vectors.md, "Replaying a set"), as the
# regeneration test (scw_regen_sets) has just made it from this build, equal to the committed set
# byte for byte or, after a width change, field for field (tests/vectors/regen_compare.sh): the
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
             COMMAND bash "${PROJECT_SOURCE_DIR}/scripts/replay.sh" "regen/${_set}"
                     "replay/${_sim}/${_work}" --simulator ${_sim}
             WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
    set_tests_properties("${_name}" PROPERTIES LABELS "vectors;${_sim}" TIMEOUT 300
                                               ENVIRONMENT "${SCW_REPLAY_ENV}"
                                               FIXTURES_REQUIRED scw_regen_sets)
  endforeach()
endforeach()

# A wrong expected beat in the (regenerated) pipeline set must stop both simulators, naming the
# stream, frame, row and column (tests/pipeline/tb/wrong_beat.sh changes one disparity beat).
add_test(NAME "vectors:a wrong beat in pipeline/small_street fails both simulators, named by stream, frame, row and column"
         COMMAND bash "${PROJECT_SOURCE_DIR}/tests/pipeline/tb/wrong_beat.sh"
                 regen/pipeline/small_street wrong_beat
         WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
set_tests_properties("vectors:a wrong beat in pipeline/small_street fails both simulators, named by stream, frame, row and column"
                     PROPERTIES LABELS "vectors;verilator;icarus" TIMEOUT 300
                                ENVIRONMENT "${SCW_REPLAY_ENV}" FIXTURES_REQUIRED scw_regen_sets)

# A set made at other widths (a field of scw_pkg.sv changed since) is refused in both simulators
# with both widths named, not failed on its first word (tests/vectors/stale_set.sh).
set(_name "vectors:a labelling set of other word widths is refused in both simulators, naming the widths")
add_test(NAME "${_name}"
         COMMAND bash "${CMAKE_CURRENT_SOURCE_DIR}/vectors/stale_set.sh"
                 "${PROJECT_SOURCE_DIR}/vectors/labelling/shapes" expected.hex replay/stale
         WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
set_tests_properties("${_name}" PROPERTIES LABELS "vectors;verilator;icarus" TIMEOUT 300
                                           ENVIRONMENT "${SCW_REPLAY_ENV}")

# The netlist Yosys makes of a block (scripts/replay.sh --simulator netlist: synth_xilinx, the
# netlist scripts/rtl_synth.sh times, in Icarus with Yosys's models of the 7-series cells). Only
# a block without block RAM at its set's size can run so (Yosys 0.23's RAMB18E1 and RAMB36E1
# models have no behaviour): of the committed sets, the road stage's. road/street, whose frames
# fit and install roads, found a packing of the road sums' adder into the DSP that left sum d
# undriven in the netlist (docs/vectors.md, "The synthesized netlist").
set(_name "vectors:road/street replays on the synthesized netlist in icarus")
add_test(NAME "${_name}"
         COMMAND bash "${PROJECT_SOURCE_DIR}/scripts/replay.sh" regen/road/street
                 "replay/netlist/road_street" --simulator netlist
         WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
set_tests_properties("${_name}" PROPERTIES LABELS "vectors;icarus;yosys" TIMEOUT 300 COST 20
                                           ENVIRONMENT "${SCW_REPLAY_ENV}"
                                           FIXTURES_REQUIRED scw_regen_sets)
# What it cannot run, it says: a block with block RAM, and the whole top, whose testbench probes
# the stages inside it.
add_test(NAME "vectors:a netlist replay refuses a block with block RAM, naming the RAM models"
         COMMAND bash "${PROJECT_SOURCE_DIR}/scripts/replay.sh"
                 "${PROJECT_SOURCE_DIR}/vectors/common/line_buffer" "replay/netlist/line_buffer"
                 --simulator netlist
         WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
add_test(NAME "vectors:a netlist replay refuses the whole top, naming the stages' sets"
         COMMAND bash "${PROJECT_SOURCE_DIR}/scripts/replay.sh"
                 "${PROJECT_SOURCE_DIR}/vectors/pipeline/small_street" "replay/netlist/pipeline"
                 --simulator netlist
         WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
set_tests_properties("vectors:a netlist replay refuses a block with block RAM, naming the RAM models"
                     PROPERTIES LABELS "vectors;yosys" TIMEOUT 300 ENVIRONMENT "${SCW_REPLAY_ENV}"
                     PASS_REGULAR_EXPRESSION "has block RAM, and Yosys 0.23's RAMB18E1 and RAMB36E1 models have ports but no behaviour")
set_tests_properties("vectors:a netlist replay refuses the whole top, naming the stages' sets"
                     PROPERTIES LABELS "vectors" TIMEOUT 60
                     PASS_REGULAR_EXPRESSION "probes the blocks inside scw_pipeline.*replay its stages' sets")
