# SPDX-License-Identifier: Apache-2.0
# The application layer's object classification (thesis 5.3.3): parallelepiped, SVM, network.
target_sources(scw_host PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/app/classify.cpp)
# The top level finds OpenCV with the components the stages need, which leaves ml out of
# OpenCV_LIBS; its imported target exists all the same (OpenCVModules.cmake declares every
# module). Asking again would only add up components, so this never narrows OpenCV_LIBS.
if(NOT TARGET opencv_ml)
  find_package(OpenCV REQUIRED COMPONENTS ml)
endif()
target_link_libraries(scw_host PRIVATE opencv_ml)
