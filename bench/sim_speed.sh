#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Simulation speed of the whole pipeline at the thesis configuration, side by side in one run:
# `scw sim --config thesis --frames F` on the C++ models and on every block Verilated, at each
# beat width P the build has (the RTL needs a build configured with -DSCW_THESIS_RTL=ON
# -DSCW_THESIS_RTL_PPC="1;2;4"), interleaved run by run; prints each run, then the medians in
# cycles per second and seconds per frame (docs/performance.md, "Simulation speed"):
#   bench/sim_speed.sh BUILD_DIR [FRAMES] [REPEATS] [BASELINE_BUILD_DIR]
# With BASELINE_BUILD_DIR (another build of scw, e.g. an older revision) its RTL runs (the chain,
# and the top where it has one) are timed in the same loop, so the two are compared on the same
# machine at the same moment, and whether their reports are the same is said. The RTL runs
# are also timed with SCW_SKIP_IDLE=0 (every cycle of every block evaluated, "rtl-all"), which
# shows what skipping the idle blocks' still cycles gains (docs/sim.md), with `--threads 2`
# ("rtl-2t": the chain's disparity and road stages on a second thread, docs/sim.md, whose report
# must be the one-thread chain's but for the thread count), and, where the build has
# the scw_pipeline top at that width, `--engine rtl-top` (the top as one Verilated model), whose
# report must be the chain's (tests/pipeline/sim_engines_agree.cmake).
set -euo pipefail
build="$(cd "${1:?usage: sim_speed.sh BUILD_DIR [FRAMES] [REPEATS] [BASELINE_BUILD_DIR]}" && pwd)"
frames="${2:-3}"
repeats="${3:-3}"
base="${4:-}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
scw="$build/host/cli/scw"
[ -x "$scw" ] || { echo "sim_speed.sh: no $scw; build scw first" >&2; exit 2; }
if [ -n "$base" ]; then
  base="$(cd "$base" && pwd)/host/cli/scw"
  [ -x "$base" ] || { echo "sim_speed.sh: no $base" >&2; exit 2; }
fi

# Whether a build has the thesis-size RTL at width P: `scw sim --engine rtl` refuses the others.
has_rtl() {
  "$1" sim --config thesis --ppc "$2" --frames 1 --engine "${3:-rtl}" --json "$work/probe.json" \
    >/dev/null 2>&1
}
runs=()
for p in 1 2 4; do runs+=("cpp $p $scw"); done
for p in 1 2 4; do
  if has_rtl "$scw" "$p"; then runs+=("rtl $p $scw" "rtl-all $p $scw" "rtl-2t $p $scw"); fi
  if has_rtl "$scw" "$p" rtl-top; then runs+=("rtl-top $p $scw"); fi
  if [ -n "$base" ] && has_rtl "$base" "$p"; then runs+=("rtl $p $base"); fi
  if [ -n "$base" ] && has_rtl "$base" "$p" rtl-top; then runs+=("rtl-top $p $base"); fi
done

declare -A secs cycles
for ((r = 1; r <= repeats; r++)); do
  for run in "${runs[@]}"; do
    read -r engine p bin <<<"$run"
    key="$engine $p $([ "$bin" = "$scw" ] && echo this || echo baseline)"
    t0="$(date +%s.%N)"
    skip=1 as="$engine" more=()
    case "$engine" in
      rtl-all) skip=0 as=rtl ;;
      rtl-2t) as=rtl more=(--threads 2) ;;
    esac
    SCW_SKIP_IDLE="$skip" "$bin" sim --config thesis --ppc "$p" --frames "$frames" \
      --engine "$as" "${more[@]}" --json "$work/run.json" >/dev/null 2>&1
    t1="$(date +%s.%N)"
    s="$(awk -v a="$t0" -v b="$t1" 'BEGIN {print b - a}')"
    secs[$key]+="$s "
    cycles[$key]="$(grep -o '"cycles": *[0-9]*' "$work/run.json" | head -1 | tr -dc 0-9)"
    cp "$work/run.json" "$work/${key// /_}.json"
    printf 'run %d  %-22s %8.2f s\n' "$r" "$key" "$s"
  done
done

median() { tr ' ' '\n' | grep -v '^$' | sort -g | awk '{a[NR] = $1} END {print a[int((NR + 1) / 2)]}'; }
printf '\nthesis configuration, %d frames a run, median of %d runs:\n' "$frames" "$repeats"
printf '  %-22s %10s %12s %12s %10s\n' "engine P build" "cycles" "s a run" "cycles/s" "s a frame"
for run in "${runs[@]}"; do
  read -r engine p bin <<<"$run"
  key="$engine $p $([ "$bin" = "$scw" ] && echo this || echo baseline)"
  m="$(echo "${secs[$key]}" | median)"
  printf '  %-22s %10d %12.2f %12.0f %10.3f\n' "$key" "${cycles[$key]}" "$m" \
    "$(awk -v c="${cycles[$key]}" -v m="$m" 'BEGIN {print c / m}')" \
    "$(awk -v m="$m" -v f="$frames" 'BEGIN {print m / f}')"
done
# Skipping must change nothing: each RTL run's report against the one with every cycle evaluated.
for p in 1 2 4; do
  a="$work/rtl_${p}_this.json" b="$work/rtl-all_${p}_this.json"
  [ -f "$a" ] || continue
  if cmp -s "$a" "$b"; then
    echo "P = $p: the same report (cycles, timing, results) with and without skipping"
  else
    echo "P = $p: the reports DIFFER with and without skipping" >&2
    exit 1
  fi
  if cmp -s <(grep -v '"threads"' "$a") <(grep -v '"threads"' "$work/rtl-2t_${p}_this.json"); then
    echo "P = $p: the same report on two threads as on one"
  else
    echo "P = $p: the reports DIFFER on two threads and on one" >&2
    exit 1
  fi
  # Said, not required: a baseline of another revision may rightly report other results.
  for e in rtl rtl-top; do
    o="$work/${e}_${p}_baseline.json"
    [ -f "$o" ] || continue
    if cmp -s "$work/${e}_${p}_this.json" "$o"; then
      echo "P = $p: $e reports the same as the baseline's"
    else
      echo "P = $p: $e reports differ from the baseline's"
    fi
  done
  t="$work/rtl-top_${p}_this.json"
  [ -f "$t" ] || continue
  cmake -DRTL_JSON="$a" -DTOP_JSON="$t" \
    -P "$(dirname "$0")/../tests/pipeline/sim_engines_agree.cmake"
done
