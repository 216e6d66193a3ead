# shellcheck shell=bash
# SPDX-License-Identifier: Apache-2.0
# The Yosys synthesis flow scw times and replays, written once: sourced by scripts/rtl_synth.sh
# (resources and timing) and scripts/replay.sh --simulator netlist (the same netlist, simulated).
#
# scw_synth_flow TOP [OPTION ...] prints the Yosys commands that map the design read so far onto
# 7-series cells: synth_xilinx -flatten -noiopad, with OPTIONs (e.g. -nobram) added.
# scw_yosys_run YOSYS [ARG ...] runs Yosys, with jemalloc as its allocator where installed.
#
# Shift registers are kept as flip-flops (-nosrl): Yosys 0.23's xilinx_srl ties the clock enable
# of every SRL16E / SRLC32E it makes high (upstream issue 6058, fixed after 0.23), so an enabled
# chain, a delay line that holds while its stage stalls, would be wrong in the netlist and its
# timing would leave out the enable's paths (docs/timing.md, "Two faults of Yosys 0.23").
# -nosrl also skips pmux2shiftx, which is not about shift registers: it turns one-hot case
# statements into shifts that map to wide multiplexers. The flow runs it between the two halves of
# synth_xilinx, as synth_xilinx does without -nosrl, so only the shift registers differ.
scw_synth_flow() {
  local top="$1"
  shift
  local opts="-flatten -noiopad -nosrl${*:+ $*} -top ${top}"
  echo "synth_xilinx ${opts} -run :map_dsp"
  echo "pmux2shiftx"
  echo "clean"
  echo "synth_xilinx ${opts} -run map_dsp:"
}

# Yosys's netlists are many small objects, and glibc's allocator is about a fifth of its
# processor time. With Debian's jemalloc (libjemalloc2, scripts/deps.sh) preloaded the same runs
# take about 27 % less and write the same cell counts, timing reports and netlists
# (docs/performance.md, "CI time, 2026-12-06"). Without the library Yosys runs as it is;
# SCW_YOSYS_JEMALLOC=0 asks for glibc's allocator. ldconfig -p is read to its end (no early exit
# under pipefail) and may be missing: then there is no jemalloc to find.
scw_jemalloc_path() {
  [[ "${SCW_YOSYS_JEMALLOC:-1}" != 0 ]] || return 0
  local ldconfig
  ldconfig="$(command -v ldconfig || echo /sbin/ldconfig)"
  { "$ldconfig" -p 2>/dev/null || true; } |
    awk '$1 == "libjemalloc.so.2" && lib == "" { lib = $NF } END { print lib }'
}

scw_yosys_run() {
  local lib
  lib="$(scw_jemalloc_path)"
  if [[ -n "$lib" ]]; then
    LD_PRELOAD="${lib}${LD_PRELOAD:+:${LD_PRELOAD}}" "$@"
  else
    "$@"
  fi
}
