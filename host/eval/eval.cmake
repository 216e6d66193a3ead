# SPDX-License-Identifier: Apache-2.0
# `scw eval`'s logic: reading truth and results, the comparison, the report, the plots and what
# surface decided each frame.
# CMAKE_CURRENT_LIST_DIR, so the paths hold wherever this file is included from.
target_sources(scw_host PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/records.cpp ${CMAKE_CURRENT_LIST_DIR}/compare.cpp
  ${CMAKE_CURRENT_LIST_DIR}/report.cpp ${CMAKE_CURRENT_LIST_DIR}/chart.cpp
  ${CMAKE_CURRENT_LIST_DIR}/plots.cpp ${CMAKE_CURRENT_LIST_DIR}/surfaces.cpp)
