#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# `scw run --shard I/N` and `scw merge` against one process (docs/slurm.md): a short synthetic
# sequence run once with --segments 3 and as 3 shards (uneven: 7 frames), the shards merged; every
# file of the merge must equal the one process's byte for byte, and the file lists must match.
# Then the merge must refuse a missing shard, a shard given twice, shards of another N or other
# settings, and a folder that is no shard, each with its message.
# usage: shard_run.sh SCW WORK_DIR
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/same_files.sh"
scw=$1 work=$2
rm -rf "$work" && mkdir -p "$work" && cd "$work"
"$scw" scene --preset cyclist-crossing --frames 7 --subsamples 1 --out-dir seq >/dev/null 2>&1
run=(run --calib seq/calibration.yml --sequence seq --min-disp 12 --max-disp 56 --window 21
     --tiles 8x4 --pictures overlay)

refuses() {  # refuses MESSAGE ARGS...: scw merge ARGS fails, saying MESSAGE
  local msg=$1
  shift
  if "$scw" merge "$@" 2>err.txt; then echo "FAIL: merge $* did not refuse"; exit 1; fi
  grep -q -- "$msg" err.txt || { echo "FAIL: merge $* said:"; cat err.txt; exit 1; }
}

"$scw" "${run[@]}" --segments 3 --out-dir one >/dev/null 2>&1
for i in 0 1 2; do "$scw" "${run[@]}" --shard $i/3 --out-dir s$i >/dev/null 2>&1; done
"$scw" merge s2 s0 s1 --out-dir merged
test "$(wc -l < merged/results.jsonl)" -eq 7 || { echo "FAIL: not 7 results"; exit 1; }
test "$(ls merged/*_overlay.png | wc -l)" -eq 7 || { echo "FAIL: not 7 overlays"; exit 1; }
same_files one merged
# The shards' blocks: floor(i * 7 / 3) .. : 2, 2 and 3 frames.
for i in 0 1 2; do echo "s$i: $(wc -l < s$i/results.jsonl) frames"; done | tr '\n' ' '
test "$(cat s0/results.jsonl s1/results.jsonl s2/results.jsonl | wc -l)" -eq 7
test "$(wc -l < s2/results.jsonl)" -eq 3 || { echo "FAIL: shard 2/3 of 7 is not frames 4 .. 6"; exit 1; }
echo "merged == one process (--segments 3), $(find merged -type f | wc -l) files"

refuses "shard(s) 1 of 3 missing" s0 s2 --out-dir bad
refuses "are both shard 0/3" s0 s0 s1 s2 --out-dir bad
refuses "holds no shard.json" s0 s1 s2 seq --out-dir bad
"$scw" "${run[@]}" --shard 1/2 --out-dir half1 >/dev/null 2>&1
refuses "(N: 3 against 2)" s0 half1 s2 --out-dir bad
"$scw" "${run[@]}" --shard 1/3 --kalman --out-dir other1 >/dev/null 2>&1
refuses "(settings: none against kalman=true)" s0 other1 s2 --out-dir bad
refuses "is shard 0's folder" s0 s1 s2 --out-dir s0
if "$scw" "${run[@]}" --shard 0/3 --segments 4 --out-dir bad >/dev/null 2>err.txt ||
   ! grep -q "give a multiple of N" err.txt; then
  echo "FAIL: --segments 4 with --shard 0/3 not refused"; exit 1
fi
echo "refusals: missing, twice, not a shard, another N, other settings, into a shard, --segments"
