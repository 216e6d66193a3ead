#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Synthesise one RTL module with Yosys synth_xilinx and print its 7-series resources (docs/rtl.md).
#
# Usage: scripts/rtl_synth.sh <module> [Param=value ...] [options]
#   --log FILE      write the full Yosys log to FILE (default: a temporary directory, removed
#                   unless the run fails)
#   --expect-bram   fail unless the design uses a RAMB18E1/RAMB36E1, no LUT RAM, and fewer
#                   than --max-ff flip-flops (proves a memory went to block RAM)
#   --max-ff N      flip-flop limit for --expect-bram (default 200)
#   --cells         print every cell type and count, not only the summary
#   --no-ltp        skip the logic-depth measurement (ltp) on very large designs
#   --path FILE     write the deepest path (ltp, cut at DSPs) cell by cell to FILE
#   --no-sta        skip static timing (sta) on very large designs
#   --sta-path FILE write the worst timing path (Yosys sta, cell by cell) to FILE
#   --max-sta-ps N  fail (exit 3) when the worst register-to-register path is longer than N ps
#
# Reads the files listed by scripts/rtl_lint.sh --files <module>, applies the parameters
# with chparam, runs `synth_xilinx -flatten -noiopad -nosrl -top <module>` (scripts/synth_flow.sh:
# shift registers as flip-flops, as Yosys 0.23 maps their enables wrong; no I/O buffers: a path into
# an output port then ends at the port), `stat`, and `ltp -noff` with
# flip-flops, block RAMs and I/O buffers excluded, and prints one line:
#   <module> [Param=value ...]: LUT=.. FF=.. RAMB18=.. RAMB36=.. DSP=.. LUTRAM=.. SRL=..
#   logic_levels=.. logic_levels_dsp_cut=.. yosys_s=..
# LUT counts LUT1..LUT6 (and LUT6_2), FF counts FD* cells, logic_levels is the longest
# register-to-register (or port) path in cells (Yosys `ltp`: LUTs, CARRY4s, MUXF7/8 each
# count one; flip-flops, SRL shift registers and block RAMs end a path); logic_levels_dsp_cut also cuts paths at DSP48E1s, whose packed pipeline registers
# ltp cannot see. sta_ps is the worst path in ps from Yosys `sta` with the 7-series cell delays
# of +/xilinx/cells_sim.v read again with their specify blocks (prjxray numbers, zero routing),
# sta_from/sta_to its start and end cells (docs/timing.md); the run fails (exit 1) when a cell
# has no timing arcs or the worst path does not end at a flip-flop, block RAM, DSP or shift
# register, rather than print a number that left part of the design out.
# Environment: YOSYS (default: yosys on PATH). Needs only bash, grep, sed, awk.
set -euo pipefail

usage() {
  echo "usage: scripts/rtl_synth.sh <module> [Param=value ...] [--log FILE] [--expect-bram]" \
    "[--max-ff N] [--cells] [--no-ltp] [--path FILE] [--no-sta] [--sta-path FILE] [--max-sta-ps N]" >&2
  exit 2
}

script_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$script_dir/.." && pwd)"
# shellcheck source=scripts/synth_flow.sh
. "$script_dir/synth_flow.sh"

module=""
params=()
log=""
expect_bram=0
max_ff=200
show_cells=0
run_ltp=1
path_out=""
run_sta=1
sta_path_out=""
max_sta_ps=""
while [[ $# -gt 0 ]]; do
  case "$1" in
    --log) [[ $# -ge 2 ]] || usage; log="$2"; shift 2 ;;
    --log=*) log="${1#--log=}"; shift ;;
    --expect-bram) expect_bram=1; shift ;;
    --max-ff) [[ $# -ge 2 ]] || usage; max_ff="$2"; shift 2 ;;
    --max-ff=*) max_ff="${1#--max-ff=}"; shift ;;
    --cells) show_cells=1; shift ;;
    --no-ltp) run_ltp=0; shift ;;
    --path) [[ $# -ge 2 ]] || usage; path_out="$2"; shift 2 ;;
    --no-sta) run_sta=0; shift ;;
    --sta-path) [[ $# -ge 2 ]] || usage; sta_path_out="$2"; shift 2 ;;
    --max-sta-ps) [[ $# -ge 2 ]] || usage; max_sta_ps="$2"; shift 2 ;;
    -h|--help) usage ;;
    -*) echo "rtl_synth: unknown option $1" >&2; usage ;;
    *=*)
      if [[ ! "$1" =~ ^[A-Za-z_][A-Za-z0-9_]*=.+$ ]]; then
        echo "rtl_synth: expected Param=value, got '$1'" >&2
        exit 2
      fi
      params+=("$1"); shift ;;
    *)
      [[ -z "$module" ]] || usage
      module="$1"; shift ;;
  esac
done
[[ -n "$module" ]] || usage
[[ "$max_ff" =~ ^[0-9]+$ ]] || { echo "rtl_synth: --max-ff needs a number" >&2; exit 2; }
[[ -z "$max_sta_ps" || "$max_sta_ps" =~ ^[0-9]+$ ]] ||
  { echo "rtl_synth: --max-sta-ps needs a number of ps, got '${max_sta_ps}'" >&2; exit 2; }

yosys="${YOSYS:-yosys}"
if ! command -v "$yosys" > /dev/null 2>&1; then
  echo "rtl_synth: '${yosys}' not found; install Yosys 0.23 or set YOSYS" >&2
  exit 1
fi

listing="$(bash "$script_dir/rtl_lint.sh" --files "$module")"

work="$(mktemp -d "${TMPDIR:-/tmp}/scw_rtl_synth.XXXXXX")"
keep_work=0
cleanup() {
  if [[ $keep_work -eq 0 ]]; then
    rm -rf "$work"
  fi
}
trap cleanup EXIT
if [[ -z "$log" ]]; then
  log="$work/yosys.log"
  own_log=1
else
  mkdir -p "$(dirname "$log")"
  own_log=0
fi

# Yosys splits script lines at blanks, so the script names files through a link to the
# repository root and runs inside the work directory: no absolute path reaches Yosys.
ln -s "$root" "$work/root"
read_files=""
libdirs=""
while read -r kind path; do
  case "$kind" in
    file) read_files+=" root/$path" ;;
    libdir) libdirs+=" -libdir root/$path" ;;
  esac
done <<< "$listing"

chparam=""
for p in "${params[@]+"${params[@]}"}"; do
  chparam+=" -set ${p%%=*} ${p#*=}"
done

{
  echo "read_verilog -sv${read_files}"
  if [[ -n "$chparam" ]]; then
    echo "chparam${chparam} ${module}"
  fi
  echo "hierarchy -check -top ${module}${libdirs}"
  scw_synth_flow "${module}"
  echo "tee -q -o stat.txt stat"
  if [[ $run_ltp -eq 1 ]]; then
    # Xilinx flip-flops are not "FF cell types" to ltp -noff (those are Yosys' internal
    # $_DFF_*), so select them away, with block RAMs (registered) and I/O buffers.
    echo "tee -q -o ltp.txt ltp -noff t:FD* t:SRL* t:RAMB* t:IBUF t:OBUF t:BUFG %u %u %u %u %u %n"
    # The same with DSP48E1s cut too: Yosys packs pipeline registers into the DSPs (A/B/P
    # registers), and ltp walks through a DSP as if it were logic.
    echo "tee -q -o ltp_dsp.txt ltp -noff t:FD* t:SRL* t:RAMB* t:IBUF t:OBUF t:BUFG t:DSP48E1 %u %u %u %u %u %u %n"
  fi
  if [[ $run_sta -eq 1 ]]; then
    # The cells again, now with their specify blocks: without them sta has no delay for a
    # CARRY4, DSP48E1 or block RAM and silently walks around them.
    echo "read_verilog -lib -specify +/xilinx/cells_sim.v"
    echo "tee -q -o sta.txt sta"
  fi
} > "$work/synth.ys"

label="$module${params[*]+ ${params[*]}}"
t0="$(date +%s%N)"
status=0
(cd "$work" && scw_yosys_run "$yosys" -q -l "$log" -s synth.ys > console.txt 2>&1) || status=$?
t1="$(date +%s%N)"
secs="$(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.1f", (b - a) / 1e9 }')"

if [[ $status -ne 0 ]]; then
  keep_work=$own_log
  echo "rtl_synth: ${label}: Yosys failed (exit ${status}) after ${secs} s" >&2
  grep -E 'ERROR|[Ee]rror:' "$log" | head -n 20 >&2 || true
  echo "--- last lines of the log ---" >&2
  tail -n 12 "$log" >&2
  echo "rtl_synth: full log: ${log}" >&2
  exit 1
fi

# Cell table of the (single, flattened) top module: "     <type>   <count>".
cells="$(awk '
  /^=== / { sections++ }
  sections == 1 && /Number of cells:/ { incells = 1; next }
  sections == 1 && incells && NF == 2 && $2 ~ /^[0-9]+$/ { print $1, $2; next }
  sections == 1 && incells && NF == 0 { incells = 0 }
' "$work/stat.txt")"

# No `printf | head` (or grep -q, or an awk that exits) below: under pipefail the writer of a pipe
# its reader left early dies of SIGPIPE and the script with it (exit 141). Here-strings and
# readers that read to the end (sed -n 1p) cannot.
sum_cells() {  # sum the counts of cell types matching an extended regex
  awk -v re="$1" '$1 ~ re { n += $2 } END { print n + 0 }' <<<"$cells"
}
lut="$(sum_cells '^LUT[1-6](_2)?$')"
ff="$(sum_cells '^FD[A-Z]*(_1)?$')"
ramb18="$(sum_cells '^RAMB18E1$')"
ramb36="$(sum_cells '^RAMB36E1$')"
dsp="$(sum_cells '^DSP48E1$')"
lutram="$(sum_cells '^RAM[0-9]+(X[0-9]+[SD]|M[0-9]*)$')"
srl="$(sum_cells '^SRLC?[0-9]+E$')"

levels="n/a"
levels_dsp="n/a"
if [[ $run_ltp -eq 1 ]]; then
  levels_dsp="$(sed -n 's/.*Longest topological path.*(length=\([0-9]*\)).*/\1/p' \
    "$work/ltp_dsp.txt" | sed -n 1p)"
  [[ -n "$levels_dsp" ]] || levels_dsp="0"
  levels="$(sed -n 's/.*Longest topological path.*(length=\([0-9]*\)).*/\1/p' "$work/ltp.txt" \
    | sed -n 1p)"
  [[ -n "$levels" ]] || levels="0"
  [[ -z "$path_out" ]] || cp "$work/ltp_dsp.txt" "$path_out"
  if grep -q 'Detected loop' "$work/ltp.txt"; then
    echo "rtl_synth: ${label}: WARNING: ltp found a combinational loop (see ltp in the log)" >&2
    levels="${levels}(loop)"
  fi
fi

sta_ps="n/a"
sta_from="n/a"
sta_to="n/a"
if [[ $run_sta -eq 1 ]]; then
  if grep -q 'has no timing arcs' "$log"; then
    keep_work=$own_log
    echo "rtl_synth: ${label}: sta: cells without timing arcs, the path would leave them out:" >&2
    grep 'has no timing arcs' "$log" | sort -u | sed -n 1,10p >&2
    exit 1
  fi
  sta_ps="$(sed -n "s/^Latest arrival time in '.*' is \([0-9]*\):.*/\1/p" "$work/sta.txt" |
    sed -n 1p)"
  if [[ -z "$sta_ps" ]]; then
    keep_work=$own_log
    echo "rtl_synth: ${label}: sta printed no latest arrival time (log: ${log})" >&2
    exit 1
  fi
  # The path, latest first: "<ps> <cell> (<TYPE>.<from>-><to>)" per hop, each followed by the
  # net it drives; the end is "<ps> <cell> (<TYPE>.<pin>)" at a timed pin, or "<ps> (<primary
  # output>)" / "<ps> (<unknown>)" when the latest arrival is at a net with no timed pin.
  path="$(awk '/^Latest arrival time/ { on = 1; next } on && NF == 0 { exit }
               on && $1 ~ /^[0-9]+$/ && $NF ~ /^\(/ && $NF !~ /input>\)$/ { print $1, $NF }' \
    "$work/sta.txt")"
  sta_to="$(awk 'NR == 1 { gsub(/[()]/, "", $2); print $2 }' <<<"$path")"
  last_hop="$(awk 'NR == 2 { gsub(/[()]/, "", $2); print $2 }' <<<"$path")"
  # The start: the launching cell after the clock buffer, or the input port a path starts at.
  if grep -q ' (BUFG\.' <<<"$path"; then
    sta_from="$(awk '{ gsub(/[()]/, "", $2) } $2 ~ /^BUFG\./ { print prev; exit }
                     { prev = $2 }' <<<"$path")"
  else
    sta_from="input:$(sed -n 's/^ *[0-9]* *\\*\(.*[^ ]\) *(<primary input>).*/\1/p' "$work/sta.txt" | sed -n 1p | tr -d ' ')"
  fi
  case "$sta_to" in
    FD*.*|RAMB18E1.*|RAMB36E1.*|DSP48E1.*|SRL16E.*|SRLC32E.*) ;;
    RAM[0-9]*M.*|RAM[0-9]*X1[DS].*) ;;  # LUT RAM: its write port is clocked
    "<primary output>") sta_to="output_port" ;;  # a module output: the path goes on outside
    "<unknown>")
      # Yosys takes the latest arrival over every net. The unused nets a 7-series netlist is
      # full of are the spare outputs of wide cells: the top of a carry chain (CARRY4 O/CO), the
      # block RAM and DSP output bits a narrower word leaves over, and a LUT RAM's write port's
      # own read output (RAM32M/RAM64M's DOD, unused in simple dual-port use). Their arrival is
      # the cell's, so the figure still covers the logic. Any other untimed end is refused.
      if [[ "$last_hop" =~ ^CARRY4\.[A-Z0-9]+-\>C?O$ ]]; then
        sta_to="unused_carry_output"
      elif [[ "$last_hop" =~ ^(RAMB18E1|RAMB36E1|DSP48E1|RAM32M|RAM64M)\. ]]; then
        sta_to="unused_${last_hop%%.*}_output"
      else
        keep_work=$own_log
        echo "rtl_synth: ${label}: sta's worst path ends at a net with no timed pin after" \
          "'${last_hop}': the number would not be a clock period (log: ${log})" >&2
        exit 1
      fi ;;
    *)
      keep_work=$own_log
      echo "rtl_synth: ${label}: sta's worst path ends at '${sta_to}', not at a flip-flop," \
        "block RAM, LUT RAM, DSP, shift register or output: the number would not be a clock" \
        "period" >&2
      exit 1 ;;
  esac
  [[ -z "$sta_path_out" ]] || cp "$work/sta.txt" "$sta_path_out"
fi

if [[ $show_cells -eq 1 || $expect_bram -eq 1 ]]; then
  echo "cells of ${label} after synth_xilinx -flatten:"
  printf '%s\n' "$cells" | awk '{ printf "  %-12s %8d\n", $1, $2 }'
fi
echo "${label}: LUT=${lut} FF=${ff} RAMB18=${ramb18} RAMB36=${ramb36} DSP=${dsp}" \
  "LUTRAM=${lutram} SRL=${srl} logic_levels=${levels} logic_levels_dsp_cut=${levels_dsp}" \
  "sta_ps=${sta_ps} sta_from=${sta_from} sta_to=${sta_to} yosys_s=${secs}"
if [[ -n "$max_sta_ps" && "$sta_ps" =~ ^[0-9]+$ && $sta_ps -gt $max_sta_ps ]]; then
  echo "rtl_synth: ${label}: TIMING FAILED: worst path ${sta_ps} ps > ${max_sta_ps} ps," \
    "from ${sta_from} to ${sta_to}:" >&2
  awk '/^Latest arrival time/ { on = 1 } on && NF == 0 { exit } on' "$work/sta.txt" |
    sed -n '1,80p' >&2
  exit 3
fi

if [[ $expect_bram -eq 1 ]]; then
  fail=""
  if [[ $((ramb18 + ramb36)) -lt 1 ]]; then
    fail+=" no RAMB18E1/RAMB36E1;"
  fi
  if [[ $lutram -ne 0 ]]; then
    fail+=" ${lutram} LUT RAM cells;"
  fi
  if [[ $ff -ge $max_ff ]]; then
    fail+=" ${ff} flip-flops (limit ${max_ff});"
  fi
  if [[ -n "$fail" ]]; then
    [[ $own_log -eq 1 ]] && keep_work=1
    echo "rtl_synth: ${label}: block RAM check FAILED:${fail%;} (log: ${log})" >&2
    exit 1
  fi
  echo "rtl_synth: ${label}: block RAM check passed (RAMB18=${ramb18} RAMB36=${ramb36}," \
    "LUTRAM=0, FF=${ff} < ${max_ff})"
fi
if [[ $own_log -eq 0 ]]; then
  echo "rtl_synth: log: ${log}"
fi
