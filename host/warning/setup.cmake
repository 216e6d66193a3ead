# SPDX-License-Identifier: Apache-2.0
# The warning stage's parameters in SI units and their fixed-point form.
target_sources(scw_host PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/warning/setup.cpp)
