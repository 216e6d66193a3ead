# SPDX-License-Identifier: Apache-2.0
# The warning model run over an object table (run_warning) for the CLI, vectors and checks, and
# the golden-vector generator with its reader of users' object tables.
target_sources(scw_host PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/warning/run_model.cpp
                                ${CMAKE_CURRENT_SOURCE_DIR}/vectors/warning_set.cpp
                                ${CMAKE_CURRENT_SOURCE_DIR}/vectors/object_tables.cpp)
