# SPDX-License-Identifier: Apache-2.0
# The warning stage's floating-point reference (Eigen, metres) for the fixed-point checks.
target_sources(scw_host PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/warning/reference.cpp)
