# SPDX-License-Identifier: Apache-2.0
# The Fig. 5.11 b overlay: driving tunnel, distance marks and the deciding object's cuboid.
target_sources(scw_host PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/warning/overlay.cpp)
