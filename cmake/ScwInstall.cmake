# SPDX-License-Identifier: Apache-2.0
# `cmake --install`: where a package manager would put scw (docs/install.md).
#   include/scw/{hls,sim,host}/...   the headers (include paths as in the source tree)
#   lib/libscw_{sim,host}.a          scw::hls is header only
#   lib/cmake/scw/                   scwConfig.cmake: scw::hls, scw::sim, scw::host, scw_rtl_files()
#   bin/scw                          the command line tool
#   share/scw/rtl_models/            every .sv, and <top>.f: the files of one top in compile order
include(CMakePackageConfigHelpers)

install(TARGETS scw_hls scw_sim scw_host EXPORT scwTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(TARGETS scw RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
foreach(dir hls sim host)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${dir} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/scw
          FILES_MATCHING PATTERN "*.hpp" PATTERN "*.def")
endforeach()
install(FILES ${PROJECT_BINARY_DIR}/generated/scw_pkg.hpp DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/scw)
# The C-synthesis tops beside their header: the files an HLS tool is pointed at (docs/hls.md).
install(DIRECTORY ${PROJECT_SOURCE_DIR}/hls/tops DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/scw/hls
        FILES_MATCHING PATTERN "*.cpp" PATTERN "*.tcl")
install(EXPORT scwTargets NAMESPACE scw:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/scw)

# One file list per top: the package, the shared primitives, then the top's stage folders (or
# the one file of a block that stands alone), paths relative to the list (verilator -F,
# iverilog -c after Yosys, any flow that takes a list).
set(SCW_RTL_TOPS
    "scw_line_buffer=" "scw_rectify=rectify" "scw_rectify_map_grid=rectify"
    "scw_disparity=disparity" "scw_road=road" "scw_ground=ground" "scw_labelling=labelling"
    "scw_warning=warning" "scw_frame_check=pipeline/scw_frame_check.sv"
    "scw_result_merge=pipeline/scw_result_merge.sv"
    "scw_pipeline=rectify,disparity,road,labelling,warning,pipeline")
set(_rtl ${PROJECT_SOURCE_DIR}/rtl_models)
file(GLOB _common RELATIVE ${_rtl} CONFIGURE_DEPENDS ${_rtl}/common/*.sv)
list(REMOVE_ITEM _common common/scw_pkg.sv)
list(SORT _common)
foreach(entry IN LISTS SCW_RTL_TOPS)
  string(REPLACE "=" ";" kv "${entry}")
  list(GET kv 0 top)
  list(LENGTH kv n)
  set(files common/scw_pkg.sv ${_common})
  if(n GREATER 1)
    list(GET kv 1 parts)
    string(REPLACE "," ";" parts "${parts}")
    foreach(part IN LISTS parts)
      if(part MATCHES "\\.sv$")
        list(APPEND files ${part})
      else()
        file(GLOB stage RELATIVE ${_rtl} CONFIGURE_DEPENDS ${_rtl}/${part}/*.sv)
        list(SORT stage)
        list(APPEND files ${stage})
      endif()
    endforeach()
  endif()
  list(JOIN files "\n" text)
  file(WRITE ${PROJECT_BINARY_DIR}/rtl_models/${top}.f "${text}\n")
  # The same list as a FuseSoC core (CAPI2), for flows that take cores: `fusesoc run --target
  # lint scw:rtl:<top>` once the installed folder is a FuseSoC library.
  list(JOIN files "\n      - " core_files)
  file(WRITE ${PROJECT_BINARY_DIR}/rtl_models/${top}.core
       "CAPI=2:\nname: scw:rtl:${top}:${PROJECT_VERSION}\n"
       "description: ${top} from scw, synthesizable SystemVerilog (docs/install.md)\n"
       "filesets:\n  rtl:\n    file_type: systemVerilogSource\n    files:\n      - ${core_files}\n"
       "targets:\n  default:\n    filesets: [rtl]\n    toplevel: ${top}\n"
       "  lint:\n    default_tool: verilator\n    filesets: [rtl]\n    toplevel: ${top}\n"
       "    tools:\n      verilator:\n        mode: lint-only\n")
  install(FILES ${PROJECT_BINARY_DIR}/rtl_models/${top}.f ${PROJECT_BINARY_DIR}/rtl_models/${top}.core
          DESTINATION ${CMAKE_INSTALL_DATADIR}/scw/rtl_models)
endforeach()
install(DIRECTORY ${_rtl}/ DESTINATION ${CMAKE_INSTALL_DATADIR}/scw/rtl_models
        FILES_MATCHING PATTERN "*.sv")

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/scwConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/scwConfig.cmake
                              INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/scw
                              PATH_VARS CMAKE_INSTALL_DATADIR)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/scwConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/scwConfig.cmake ${PROJECT_BINARY_DIR}/scwConfigVersion.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/scw)
