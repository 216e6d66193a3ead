#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Replays one golden vector set against its RTL block with a self-checking testbench, the way a
# user replays it in their own simulator (docs/vectors.md, "Replaying a set"):
#   scripts/replay.sh SET WORKDIR [--simulator verilator|icarus|netlist] [+plusarg ...]
# The set's manifest.json names its stage; the table below says, per stage, the testbench, the
# RTL files, which manifest keys are the block's parameters, the testbench's and its plusargs.
#   verilator  Verilator 5.006 --binary on the SystemVerilog sources (2-state: an X reads as 0).
#   icarus     Yosys reads the same sources at the set's parameters and writes the block as plain
#              Verilog (proc; flatten, but not for the whole top, whose testbench probes its
#              stages; write_verilog), which Icarus Verilog 11 runs with the same
#              testbench, 4-state: an X on a compared output fails the replay. It is the design
#              as synthesis reads it.
#   netlist    Icarus as above, on the netlist Yosys 0.23's synth_xilinx makes of the block (the
#              one scripts/rtl_synth.sh counts and times) with Yosys's models of the 7-series
#              cells: what synthesis made of the design, not what it read (docs/vectors.md).
#              SCW_NETLIST_SYNTH_OPTS adds synth_xilinx options (-nobram).
# Extra +plusargs go to the testbench (e.g. +stalls=0). Prints the testbench's PASS line, or its
# first differing beat; exits non-zero on any failure.
# SCW_REPLAY_CACHE=DIR (optional): a folder replays share, so that what one builds the next
# does not build again: Verilator's own runtime objects (verilated.o and friends, the same for
# every testbench built with the same Verilator and options: about 7 of a replay's 10 s of
# compile), each Verilated testbench (one for every set of a block at one size: the set's counts
# are plusargs), and each block as Yosys writes it for Icarus. An entry is
# keyed by the tool's version, its options and parameters and the content of every file it
# reads, so an edited source or another parameter builds anew. The test suite sets it.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
usage() {
  echo "usage: replay.sh SET WORKDIR [--simulator verilator|icarus|netlist] [+plusarg ...]" >&2
  exit 2
}
[ $# -ge 2 ] || usage
set_dir="$1"
work="$2"
shift 2
simulator=verilator
extra=()
while [ $# -gt 0 ]; do
  case "$1" in
    --simulator) [ $# -ge 2 ] || usage; simulator="$2"; shift 2 ;;
    +*) extra+=("$1"); shift ;;
    *) echo "replay.sh: unknown argument '$1'" >&2; usage ;;
  esac
done
case "$simulator" in
  verilator | icarus | netlist) ;;
  *) echo "replay.sh: --simulator is verilator, icarus or netlist, not '$simulator'" >&2; exit 2 ;;
esac
[ -f "$set_dir/manifest.json" ] ||
  { echo "replay.sh: no manifest.json in '$set_dir': give a vector set folder" >&2; exit 2; }
set_dir="$(cd "$set_dir" && pwd)"
manifest="$set_dir/manifest.json"

# A value of the manifest's config block by key: an integer (possibly negative) or a boolean
# (true/false -> 1/0). Only the text before the file table is read, so a key the config lacks
# is refused rather than taken from a file's entry (width, height, beats; a file's own numbers
# are file_field's).
field() {
  local v
  v="$(sed '/"files": *\[/q' "$manifest" | grep -o "\"$1\": *[-a-z0-9]*" | head -1 |
    sed 's/.*: *//' | sed 's/^true$/1/; s/^false$/0/')"
  [[ "$v" =~ ^-?[0-9]+$ ]] || { echo "replay.sh: no number '$1' in $manifest" >&2; exit 2; }
  echo "$v"
}
# A number of one file's entry in the file table: file_field expected.hex width_bits.
file_field() {
  local v
  v="$(awk -v name="\"name\": \"$1\"" -v key="\"$2\":" '
    index($0, name) { inside = 1 }
    inside && index($0, key) { gsub(/[^0-9]/, "", $2); print $2; exit }' "$manifest")"
  [[ "$v" =~ ^[0-9]+$ ]] || { echo "replay.sh: no '$2' for $1 in $manifest" >&2; exit 2; }
  echo "$v"
}

# Per stage: tb (under tests/), top, rtl (under rtl_models/, after the package), the block's
# parameters and the testbench's own (Name=manifest_key), the plusargs (arg=manifest_key) and
# the set's counts (arg=manifest_key or number): its beats, words and frames, given at run time
# so that every set of a block at one size replays one build of its testbench.
stage="$(grep -o '"stage": *"[a-z_]*"' "$manifest" | head -1 | sed 's/.*: *"//; s/"$//')"
tb_params=()
tb_extra=()
plusargs=()
counts=()
flatten=1
case "$stage" in
  line_buffer)
    tb=common/tb/tb_line_buffer_replay.sv top=scw_line_buffer
    rtl=(common/scw_ram_sdp.sv common/scw_line_buffer.sv)
    dut_params=(Ppc=ppc MaxWidthPx=max_width_px Rows=rows)
    counts=("beats=$(file_field input.hex beats)") ;;
  rectify)
    tb=rectify/tb/tb_rectify_replay.sv top=scw_rectify
    rtl=(common/scw_ram_sdp.sv rectify/scw_rectify.sv)
    dut_params=(Ppc=ppc MaxWidthPx=max_width_px MaxHeight=max_height Rows=rows
                FracBits=frac_bits)
    tb_params=(CoordBits=coord_bits)
    counts=("beats=$(file_field input.hex beats)")
    plusargs=(width=width height=height lead=lead_rows) ;;
  disparity)
    tb=disparity/tb/tb_disparity_replay.sv top=scw_disparity
    rtl=(common/scw_ram_sdp.sv common/scw_delay_ring.sv
         "$(cd "$root/rtl_models" && echo disparity/*.sv)")
    dut_params=(Ppc=ppc MaxWidthPx=max_width_px MaxHeight=max_height Window=window
                NumDisp=num_disp)
    tb_params=("CfgW=$(file_field cfg.hex width_bits)")
    counts=("beats=$(file_field left.hex beats)")
    plusargs=(width=width height=height) ;;
  labelling)
    tb=labelling/tb/tb_labelling_replay.sv top=scw_labelling
    rtl=(common/scw_ram_sdp.sv common/scw_fifo.sv "$(cd "$root/rtl_models" && echo labelling/*.sv)")
    dut_params=(MaxWidthPx=max_width_px MaxHeight=max_height MaxTilesX=max_tiles_x
                MaxTilesY=max_tiles_y LabelsPerTile=labels_per_tile MaxObjects=max_objects)
    tb_params=("OutW=$(($(file_field expected.hex width_bits) - 1))"
               "CfgW=$(file_field cfg.hex width_bits)")
    counts=(beats_in=beats_in words_out=words_out frames=frames)
    plusargs=(width=width height=height) ;;
  road)
    tb=road/tb/tb_road_replay.sv top=scw_road
    rtl=("$(cd "$root/rtl_models" && echo common/*.sv road/*.sv)")
    dut_params=(Ppc=ppc MaxWidthPx=max_width_px MaxHeight=max_height)
    tb_params=(FitClocks=fit_clocks "CfgW=$(file_field cfg.hex width_bits)")
    counts=(beats=beats frames=frames)
    plusargs=(width=width height=height) ;;
  warning)
    tb=warning/tb/tb_warning_replay.sv top=scw_warning
    rtl=(common/scw_delay_ring.sv "$(cd "$root/rtl_models" && echo warning/*.sv)")
    dut_params=(MaxDisparityPx=max_disparity_px)
    tb_params=("InW=$(($(file_field in.hex width_bits) - 1))"
               "OutW=$(($(file_field expected.hex width_bits) - 1))"
               "CfgW=$(file_field cfg.hex width_bits)")
    counts=(words_in=words_in words_out=words_out) ;;
  pipeline)
    # The whole top; its testbench probes the stages' output ports by hierarchical name, so
    # Yosys keeps the hierarchy.
    tb=pipeline/tb/tb_pipeline_replay.sv top=scw_pipeline flatten=0
    tb_extra=(pipeline/tb/tb_pipeline_stream_check.sv)
    rtl=("$(cd "$root/rtl_models" && echo common/*.sv rectify/*.sv disparity/*.sv road/*.sv \
      labelling/*.sv warning/*.sv pipeline/*.sv)")
    dut_params=(Ppc=Ppc MaxWidthPx=MaxWidthPx MaxHeight=MaxHeight RectRows=RectRows
                GridLog2=GridLog2 Window=Window NumDisp=NumDisp MaxTilesX=MaxTilesX
                MaxTilesY=MaxTilesY LabelsPerTile=LabelsPerTile MaxObjects=MaxObjects
                MaxDisparityPx=MaxDisparityPx)
    tb_params=(CfgWords=cfg_words
               "WarningCfgW=$(file_field cfg_warning.hex width_bits)"
               "RoadCfgW=$(file_field cfg_road.hex width_bits)"
               "DisparityCfgW=$(file_field cfg_disparity.hex width_bits)"
               "LabellingCfgW=$(file_field cfg_labelling.hex width_bits)"
               "KnotBits=$(file_field knots.hex width_bits)"
               "ObjBits=$(file_field objects.hex width_bits)"
               "ResBits=$(file_field results.hex width_bits)")
    counts=("knots=$(file_field knots.hex beats)" "raw_beats=$(file_field left.hex beats)"
            "disp_beats=$(file_field disparity.hex beats)"
            "obj_words=$(file_field objects.hex beats)" "results=$(file_field results.hex beats)")
    plusargs=(width=width height=height) ;;
  *)
    echo "replay.sh: $manifest has stage '${stage}'; replayable stages: line_buffer rectify" \
      "disparity labelling road warning pipeline" >&2
    exit 2 ;;
esac
tb_module="$(basename "$tb" .sv)"
# Every testbench instantiates the shared clock and sources (tests/common/tb/tb_replay_kit.sv).
tb_files=("$root/tests/$tb" "$root/tests/common/tb/tb_replay_kit.sv")
for f in "${tb_extra[@]}"; do tb_files+=("$root/tests/$f"); done
read -r -a rtl <<< "${rtl[*]}"  # the globs above expand to one word each
sources=("$root/rtl_models/common/scw_pkg.sv")
for f in "${rtl[@]}"; do
  [ "$f" = common/scw_pkg.sv ] || sources+=("$root/rtl_models/$f")
done

# The value of a table entry Name=what: what itself when it is a number, else the manifest's key.
value_of() {
  local v="${1#*=}"
  [[ "$v" =~ ^[0-9]+$ ]] || v="$(field "$v")"
  echo "$v"
}
# Name=value for the block's parameters and the testbench's (which repeats the block's).
dut_values=()
for kv in "${dut_params[@]}"; do dut_values+=("${kv%%=*}=$(value_of "$kv")"); done
tb_values=("${dut_values[@]}")
for kv in "${tb_params[@]}"; do tb_values+=("${kv%%=*}=$(value_of "$kv")"); done
args=(+vectors="$set_dir")
for kv in "${plusargs[@]}"; do args+=("+${kv%%=*}=$(value_of "$kv")"); done
# The counts: plusargs, and Cap, the testbench's array size, a power of two from 16384 up, so that
# the sets of a block at one size (up to 16384 beats or words each) share one build.
cap=16384
for kv in "${counts[@]}"; do
  v="$(value_of "$kv")"
  args+=("+${kv%%=*}=$v")
  while [ "$cap" -lt "$v" ]; do cap=$((cap * 2)); done
done
tb_values+=("Cap=$cap")
args+=("${extra[@]}")

mkdir -p "$work"
: >"$work/build.log"
cache="${SCW_REPLAY_CACHE:-}"
# digest TEXT FILE...: a key of TEXT and the files' contents.
digest() { { echo "$1"; shift; cat "$@"; } | md5sum | cut -c1-16; }
# cached NAME KEY RESULT COMMAND...: runs COMMAND, which makes the file RESULT, unless the cache
# holds RESULT from a run with the same KEY, which is then copied instead. One replay at a time
# per key: a second one waits for the first's result.
cached() {
  local name="$1" key="$2" result="$3"
  shift 3
  if [ -z "$cache" ]; then "$@"; return; fi
  local entry="$cache/$name-$key"
  mkdir -p "$cache"
  (
    flock 9
    if [ -f "$entry/${result##*/}" ]; then
      cp "$entry/${result##*/}" "$result"
      echo "replay.sh: $name built before, taken from $entry" >>"$work/build.log"
    else
      "$@"
      mkdir -p "$entry" && cp "$result" "$entry/"
    fi
  ) 9>"$entry.lock"
}
rel=("${sources[@]#"$root"/}" "${tb_files[@]#"$root"/}")

if [ "$simulator" = verilator ]; then
  gargs=()
  for kv in "${tb_values[@]}"; do gargs+=("-G$kv"); done
  # --binary, with the build step run here (`--binary` is --main --exe --build --timing), so
  # a kept runtime can be put in place between Verilator's C++ and its make.
  vargs=(--cc --main --exe --timing -Wno-fatal -Wno-lint -Wno-style)
  # The C++ at -O0 rather than Verilator's -Os: a testbench is compiled once and runs a few
  # thousand beats, so the compile is most of a replay (pipeline/small_street: 11.7 s to compile
  # and 0.11 s to run at -Os, 7.2 and 0.26 s at -O0; the thesis-size rectify set, the longest
  # run, 5.0 s against 4.6 s in all; docs/performance.md).
  mflags=(OPT_FAST=-O0 OPT_SLOW=-O0 OPT_GLOBAL=-O0)
  build_verilator() {
    verilator "${vargs[@]}" --top-module "$tb_module" \
      "${gargs[@]}" "${sources[@]}" "${tb_files[@]}" -Mdir "$work/obj" >>"$work/build.log" 2>&1 ||
      { cat "$work/build.log"; exit 1; }
    local runtime=""
    if [ -n "$cache" ]; then
      # Keyed by the Verilator and the options, which are all the runtime's compile depends on.
      runtime="$cache/runtime-$(digest "$(verilator --version) ${vargs[*]} ${mflags[*]}")"
      mkdir -p "$runtime"
      # Copied without their times: newer than the makefile Verilator just wrote, make takes
      # them as built.
      (flock 9; cp "$runtime"/verilated*.[od] "$work/obj/" 2>/dev/null || true) 9>"$runtime.lock"
    fi
    make -C "$work/obj" -f "V$tb_module.mk" "${mflags[@]}" >>"$work/build.log" 2>&1 ||
      { cat "$work/build.log"; exit 1; }
    if [ -n "$runtime" ] && ! [ -e "$runtime/verilated.o" ]; then
      (flock 9; [ -e "$runtime/verilated.o" ] || cp "$work/obj"/verilated*.[od] "$runtime/") \
        9>"$runtime.lock"
    fi
  }
  mkdir -p "$work/obj"
  cached verilator \
    "$(digest "$(verilator --version) ${vargs[*]} ${mflags[*]} $tb_module ${gargs[*]} ${rel[*]}" \
      "${sources[@]}" "${tb_files[@]}")" "$work/obj/V$tb_module" build_verilator
  "$work/obj/V$tb_module" "${args[@]}" | tee "$work/run.log"
else
  command -v iverilog >/dev/null ||
    { echo "replay.sh: iverilog is missing: apt-get install iverilog (scripts/deps.sh)" >&2; exit 1; }
  # shellcheck source=scripts/synth_flow.sh
  . "$root/scripts/synth_flow.sh"
  chparam=""
  for kv in "${dut_values[@]}"; do chparam+=" -set ${kv%%=*} ${kv#*=}"; done
  script="read_verilog -sv ${sources[*]}
chparam$chparam $top
hierarchy -check -top $top"
  cells=()
  if [ "$simulator" = netlist ]; then
    [ "$flatten" = 1 ] || { echo "replay.sh: the $stage testbench probes the blocks inside" \
      "$top, which a flattened netlist no longer has: replay its stages' sets with --simulator" \
      "netlist" >&2; exit 2; }
    # SCW_NETLIST_SYNTH_OPTS: more synth_xilinx options, e.g. -nobram to check the rest of the
    # mapping of a block with block RAM (docs/vectors.md).
    # shellcheck disable=SC2086 # the options are words
    script+=$'\n'"$(scw_synth_flow "$top" ${SCW_NETLIST_SYNTH_OPTS:-})"
    cells=("$(dirname "$(command -v yosys)")/../share/yosys/xilinx/cells_sim.v")
  elif [ "$flatten" = 1 ]; then script+=$'\nproc; flatten; opt_clean'
  else script+=$'\nproc; opt_clean'; fi
  write_dut() {
    printf '%s\nwrite_verilog -noattr %s\n' "$script" "$work/dut.v" >"$work/dut.ys"
    scw_yosys_run yosys -q -l "$work/yosys.log" -s "$work/dut.ys" >/dev/null 2>&1 ||
      { tail -20 "$work/yosys.log"; exit 1; }
  }
  # The block as Yosys writes it depends on the block's parameters only, not the testbench's:
  # every set of a block at one size shares it.
  cached yosys "$(digest "$(yosys -V) ${script//"$root"/}" "${sources[@]}")" \
    "$work/dut.v" write_dut
  if [ "$simulator" = netlist ] && grep -qE '^ *RAMB(18|36)E1 ' "$work/dut.v"; then
    echo "replay.sh: the netlist of $top at this set's parameters has block RAM, and Yosys 0.23's" \
      "RAMB18E1 and RAMB36E1 models have ports but no behaviour: its reads would be X. Replay" \
      "it with --simulator icarus, or check the rest of its mapping with" \
      "SCW_NETLIST_SYNTH_OPTS=-nobram (docs/vectors.md, \"The synthesized netlist\")" >&2
    exit 2
  fi
  pargs=()
  for kv in "${tb_values[@]}"; do pargs+=(-P "$tb_module.$kv"); done
  # The block as Yosys wrote it has no parameters left: Icarus notes the testbench's overrides
  # as "parameter not found" (in build.log), which is expected.
  iverilog -g2012 -s "$tb_module" "${pargs[@]}" -o "$work/sim.vvp" "$work/dut.v" \
    "${cells[@]}" "${tb_files[@]}" >>"$work/build.log" 2>&1 || { cat "$work/build.log"; exit 1; }
  vvp -n "$work/sim.vvp" "${args[@]}" | tee "$work/run.log"
fi
# A testbench that ends without its verdict (a $finish elsewhere) must not pass.
grep -q '^PASS: ' "$work/run.log" || { echo "replay.sh: no PASS line from the testbench" >&2; exit 1; }
