#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# `scw run` on the C++ models against the OpenCV chain a user would write instead
# (bench/opencv_chain), side by side on the 49-frame distance sweep, interleaved run by run:
#   bench/run_vs_opencv.sh BUILD_DIR [WORKDIR] [REPEATS]
# Prints each run's seconds, then the medians a frame and their ratio (docs/performance.md).
set -euo pipefail
build="$(cd "${1:?usage: run_vs_opencv.sh BUILD_DIR [WORKDIR] [REPEATS]}" && pwd)"
work="${2:-$(mktemp -d)}"
repeats="${3:-3}"
scw="$build/host/cli/scw"
chain="$build/bench/opencv_chain/opencv_chain"
for b in "$scw" "$chain"; do
  [ -x "$b" ] || { echo "run_vs_opencv.sh: no $b; build scw first" >&2; exit 2; }
done
mkdir -p "$work"
sweep="$work/sweep"
[ -f "$sweep/scene.json" ] || "$scw" scene --preset distance-sweep --out-dir "$sweep" >/dev/null 2>&1
frames="$(ls "$sweep"/*_left.png | wc -l)"
# The sweep's own settings (scene.json's command), the pictures a choice.
run_scw() {
  "$scw" run --calib "$sweep/calibration.yml" --sequence "$sweep" --min-disp 12 --max-disp 56 \
    --window 21 --tiles 8x4 --camera-height 1.2 --frame-period 16 --pictures "$1" \
    --out-dir "$work/run_$1" >/dev/null 2>&1
}
run_chain() { "$chain" "$sweep" "$sweep/calibration.yml" 12 56 21 50 >"$work/chain.txt"; }
seconds() {  # seconds COMMAND...: wall time of one run
  local t0 t1
  t0="$(date +%s.%N)"
  "$@"
  t1="$(date +%s.%N)"
  awk -v a="$t0" -v b="$t1" 'BEGIN {print b - a}'
}
declare -A all
for ((r = 1; r <= repeats; r++)); do
  for what in chain none overlay all; do
    if [ "$what" = chain ]; then s="$(seconds run_chain)"; else s="$(seconds run_scw "$what")"; fi
    all[$what]+="$s "
    printf 'run %d  %-26s %8.2f s\n' "$r" "$([ "$what" = chain ] && echo "OpenCV chain" || echo "scw run --pictures $what")" "$s"
  done
done
median() { tr ' ' '\n' | grep -v '^$' | sort -g | awk '{a[NR] = $1} END {print a[int((NR + 1) / 2)]}'; }
base="$(echo "${all[chain]}" | median)"
printf '\n%d frames (%s), median of %d runs:\n' "$frames" \
  "$(tail -1 "$work/chain.txt" | sed 's/^frames [0-9]*, //; s/:.*//')" "$repeats"
for what in chain none overlay all; do
  m="$(echo "${all[$what]}" | median)"
  printf '  %-26s %7.3f s a frame  %5.2f x the OpenCV chain\n' \
    "$([ "$what" = chain ] && echo "OpenCV chain" || echo "scw run --pictures $what")" \
    "$(awk -v m="$m" -v n="$frames" 'BEGIN {print m / n}')" \
    "$(awk -v m="$m" -v b="$base" 'BEGIN {print m / b}')"
done
