# SPDX-License-Identifier: Apache-2.0
# Warnings for scw's own targets only: third-party and Verilator-generated code stays quiet.
function(scw_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow
                                           -Wnon-virtual-dtor -Wold-style-cast
                                           # `#pragma HLS` is for the HLS tool, not g++.
                                           -Wno-unknown-pragmas)
endfunction()
