# SPDX-License-Identifier: Apache-2.0
# `scw eval`: a synthetic scene's truth against scw run's results.jsonl.
target_sources(scw PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/cmd_eval.cpp)
