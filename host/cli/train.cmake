# SPDX-License-Identifier: Apache-2.0
# `scw train`: the application layer's object classifiers (host/app/classify.hpp).
target_sources(scw PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/cmd_train.cpp)
