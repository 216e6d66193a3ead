# SPDX-License-Identifier: Apache-2.0
# `scw synth`: Yosys resource figures of every stage and the pipeline top at one build.
target_sources(scw PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/cmd_synth.cpp)
# The command runs scripts/rtl_synth.sh from the source tree it was built from (--scripts
# overrides it), so the RTL it synthesises is the RTL of this checkout.
set_property(SOURCE ${CMAKE_CURRENT_SOURCE_DIR}/cmd_synth.cpp APPEND PROPERTY
             COMPILE_DEFINITIONS "SCW_SOURCE_DIR=\"${PROJECT_SOURCE_DIR}\"")
