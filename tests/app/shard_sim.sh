#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# `scw sim --shard I/N` and `scw merge` against one process with --segments N (docs/slurm.md):
# the small build's pipeline, 5 frames on the C++ models and 4 on the Verilated blocks, each run
# once with --segments 2 and as 2 shards; the merge must equal the one process byte for byte
# (frames.jsonl and segments.jsonl), a segment must be a fresh pipeline (its first frame's input
# at cycle 0), and --json must be refused where there are several segments.
# usage: shard_sim.sh SCW WORK_DIR
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/same_files.sh"
scw=$1 work=$2
rm -rf "$work" && mkdir -p "$work" && cd "$work"
for run in "cpp 5" "rtl 4"; do
  engine=${run% *} frames=${run#* }
  sim=(sim --config small --engine "$engine" --frames "$frames")
  "$scw" "${sim[@]}" --segments 2 --out-dir "one_$engine" >/dev/null 2>&1
  for i in 1 0; do "$scw" "${sim[@]}" --shard $i/2 --out-dir "${engine}_s$i" >/dev/null 2>&1; done
  "$scw" merge "${engine}_s1" "${engine}_s0" --out-dir "merged_$engine"
  same_files "one_$engine" "merged_$engine"
  test "$(wc -l < "one_$engine/frames.jsonl")" -eq "$frames"
  test "$(wc -l < "one_$engine/segments.jsonl")" -eq 2
  # The second segment (frames 2 ..) starts a fresh pipeline: its first frame's input at cycle 0.
  grep '"frame":2,' "one_$engine/frames.jsonl" | grep -q '"first_in_cycle":0,' ||
    { echo "FAIL: frame 2 of $engine is not the first of a fresh pipeline"; exit 1; }
done
if "$scw" sim --config small --frames 2 --segments 2 --json x.json 2>err.txt; then
  echo "FAIL: --json with two segments was taken"; exit 1
fi
grep -q -- "--json writes one run's report" err.txt || { cat err.txt; exit 1; }
echo "sim: 2 shards merged == one process with --segments 2 (cpp and rtl)"
