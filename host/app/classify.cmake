# SPDX-License-Identifier: Apache-2.0
# The application layer's object classification (thesis 5.3.3): parallelepiped, SVM, network.
# One job a file: the features, the classifiers, their model files, CSV rows, the Table 5.4
# sampler and the rates (host/app/classify.hpp includes them all).
foreach(part object_features classifiers model_file feature_csv table54_sampler classify_rates)
  target_sources(scw_host PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/app/${part}.cpp)
endforeach()
# The top level finds OpenCV with the components the stages need, which leaves ml out of
# OpenCV_LIBS; its imported target exists all the same (OpenCVModules.cmake declares every
# module). Asking again would only add up components, so this never narrows OpenCV_LIBS.
if(NOT TARGET opencv_ml)
  find_package(OpenCV REQUIRED COMPONENTS ml)
endif()
target_link_libraries(scw_host PRIVATE opencv_ml)
