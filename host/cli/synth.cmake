# SPDX-License-Identifier: Apache-2.0
# `scw synth`: Yosys resource and timing figures of every stage and the pipeline top at one build
# (the work itself is host/synth/).
target_sources(scw PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/cmd_synth.cpp)
