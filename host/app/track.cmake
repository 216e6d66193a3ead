# SPDX-License-Identifier: Apache-2.0
# The application layer's tracker (thesis 5.3.3).
target_sources(scw_host PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/app/track.cpp)
# Kalman mode uses cv::KalmanFilter from OpenCV's video module, which the top level does not
# ask for; its imported target exists anyway (OpenCVModules.cmake declares every module), so
# find_package runs only as a fallback. The header does not expose OpenCV: link privately.
if(NOT TARGET opencv_video)
  find_package(OpenCV REQUIRED COMPONENTS video)
endif()
target_link_libraries(scw_host PRIVATE opencv_video)
