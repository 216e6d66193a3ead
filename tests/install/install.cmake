# SPDX-License-Identifier: Apache-2.0
# [install] `cmake --install` into a fresh prefix, then examples/downstream configured against it
# in a fresh folder: find_package(scw), the disparity stage's model, and scw_disparity Verilated
# from the installed RTL through its file list; the example exits 0 when they agree. The
# C-synthesis tops and their Vitis HLS script must be installed beside the headers.
# The example is built as one unity file a batch (CMAKE_UNITY_BUILD, a plain CMake option the
# example does not set itself): Verilator's many small files each parse verilated.h again,
# 89 job-seconds of compiling one at a time against 21 in unity (docs/performance.md). It runs a
# few hundred clocks, so it is compiled at -O1: 35 -> 25 job-seconds (docs/performance.md).
add_test(NAME "install:a downstream project finds the installed scw, runs a model, Verilates scw_disparity"
         COMMAND bash -c "rm -rf install_check && \
                          '${CMAKE_COMMAND}' --install '${PROJECT_BINARY_DIR}' \
                            --prefix \"$PWD/install_check/prefix\" > install_check.log && \
                          test -s install_check/prefix/share/scw/rtl_models/scw_pipeline.f && \
                          test -x install_check/prefix/bin/scw && \
                          test -s install_check/prefix/include/scw/hls/tops/scw_pipeline_top.cpp && \
                          test -s install_check/prefix/include/scw/hls/tops/scw_hls.tcl && \
                          '${CMAKE_COMMAND}' -S '${PROJECT_SOURCE_DIR}/examples/downstream' \
                            -B install_check/build -G '${CMAKE_GENERATOR}' \
                            -DCMAKE_PREFIX_PATH=\"$PWD/install_check/prefix\" \
                            -DCMAKE_UNITY_BUILD=ON \
                            '-DCMAKE_CXX_FLAGS_RELEASE=-O1 -DNDEBUG' >> install_check.log && \
                          '${CMAKE_COMMAND}' --build install_check/build >> install_check.log && \
                          install_check/build/downstream"
         WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
set_tests_properties("install:a downstream project finds the installed scw, runs a model, Verilates scw_disparity"
                     PROPERTIES LABELS "install" TIMEOUT 900 COST 50)
