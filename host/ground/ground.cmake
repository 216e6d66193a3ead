# SPDX-License-Identifier: Apache-2.0
# Ground-plane removal, host side: the plain-loop reference with the camera-derived defaults,
# and the model run over whole maps (remove_ground) for the CLI and the real-data checks.
target_sources(scw_host PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/reference/ground_ref.cpp
                                ${CMAKE_CURRENT_SOURCE_DIR}/ground/run_model.cpp)
