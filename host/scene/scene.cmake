# SPDX-License-Identifier: Apache-2.0
# Synthetic stereo street scenes with ground truth (docs/scene.md): the rig, its ray tables, the
# textures, the ray caster, the thesis's presets, the truth and the files; `scw scene` drives them.
target_sources(scw_host PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/scene/rig.cpp
                                ${CMAKE_CURRENT_SOURCE_DIR}/scene/rays.cpp
                                ${CMAKE_CURRENT_SOURCE_DIR}/scene/texture.cpp
                                ${CMAKE_CURRENT_SOURCE_DIR}/scene/scene.cpp
                                ${CMAKE_CURRENT_SOURCE_DIR}/scene/render.cpp
                                ${CMAKE_CURRENT_SOURCE_DIR}/scene/presets.cpp
                                ${CMAKE_CURRENT_SOURCE_DIR}/scene/street.cpp
                                ${CMAKE_CURRENT_SOURCE_DIR}/scene/truth.cpp
                                ${CMAKE_CURRENT_SOURCE_DIR}/scene/write.cpp)
