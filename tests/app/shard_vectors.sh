#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# `scw vectors <stage> --shard I/N` and `scw merge` against one process with --segments N
# (docs/slurm.md): every stage's set split in 2 segments, each a whole set of its frames in
# OUT/frames_FIRST-LAST, once in one process and once as 2 shards merged; the two folders must be
# equal byte for byte and every segment's set must verify; a segment too short for its stage is
# refused, named. The merged pipeline set is left in
# WORK_DIR/merged_pipeline for a replay (tests/app/shard.cmake).
# usage: shard_vectors.sh SCW WORK_DIR
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/same_files.sh"
scw=$1 work=$2
rm -rf "$work" && mkdir -p "$work" && cd "$work"
for set in "labelling --preset shapes --frames 5" "warning --preset thesis --frames 5" \
           "road --preset street --frames 8" "disparity --preset texture --frames 3" \
           "rectify --preset shift --frames 3" "pipeline --frames 4"; do
  read -r -a args <<< "$set"
  stage=${args[0]}
  "$scw" vectors "${args[@]}" --segments 2 --out "one_$stage" >/dev/null 2>&1 ||
    { echo "FAIL: scw vectors $set --segments 2"; exit 1; }
  for i in 1 0; do "$scw" vectors "${args[@]}" --shard $i/2 --out "${stage}_s$i" >/dev/null 2>&1; done
  "$scw" merge "${stage}_s0" "${stage}_s1" --out-dir "merged_$stage" >/dev/null
  same_files "one_$stage" "merged_$stage"
  test "$(ls "one_$stage" | wc -l)" -eq 2
  for d in "one_$stage"/frames_*; do "$scw" vectors verify "$d" >/dev/null; done
  echo "$stage: 2 shards merged == one process with --segments 2: $(ls "one_$stage" | tr '\n' ' ')"
done
# A segment too short for its stage is refused naming the segment and the fix.
if "$scw" vectors road --preset street --segments 3 --out short 2>err.txt; then
  echo "FAIL: road segments of 2 frames were written"; exit 1
fi
grep -q "frames_0000-0001, a segment of 6 frames: .*at least 4.*give fewer --segments" err.txt ||
  { cat err.txt; exit 1; }
