# SPDX-License-Identifier: Apache-2.0
# C synthesis of one top of this folder in Vitis HLS (docs/hls.md; untried: no vendor tool ran
# on this code), from the repository root:
#   vitis_hls -f hls/tops/scw_hls.tcl -tclargs scw_disparity [part] [clock period, ns]
# The build is the thesis configuration at P = 1 (hls/tops/tops.hpp); add
# -DSCW_HLS_BUILD=... to cflags for another. A C-simulation test bench (add_files -tb) is the
# project's own tests/ case for the stage, e.g. tests/pipeline/test_pipeline_hls.cpp.
set top [lindex $argv 0]
set part [expr {[llength $argv] > 1 ? [lindex $argv 1] : "xc7z020clg400-1"}]
set period [expr {[llength $argv] > 2 ? [lindex $argv 2] : 8}]
set root [file normalize [file join [file dirname [info script]] .. ..]]
set cflags "-std=c++17 -I$root -DSCW_VENDOR_HLS_STREAM"
open_project -reset ${top}_hls
set_top ${top}_top
add_files [file join $root hls tops ${top}_top.cpp] -cflags $cflags
open_solution -reset sol1 -flow_target vivado
set_part $part
create_clock -period $period
csynth_design
exit
