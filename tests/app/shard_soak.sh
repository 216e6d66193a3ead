#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# `scw soak --seeds 3` in one process and as 2 shards (--shard I/2: seeds 1, then 2 and 3),
# merged (docs/slurm.md): the same files, each equal to one process's once the wall-clock
# "seconds" (different in any two runs) are taken out, and nothing else differs.
# usage: shard_soak.sh SCW WORK_DIR TSUKUBA_DIR
set -euo pipefail
scw=$1 work=$2 tsukuba=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work"
soak=(soak --frames 6 --malformed-every 3 --resets 2 --seeds 3
      --real-left "$tsukuba/scene1.row3.col3.ppm" --real-right "$tsukuba/scene1.row3.col4.ppm")
"$scw" "${soak[@]}" --out-dir one >/dev/null 2>&1
for i in 0 1; do "$scw" "${soak[@]}" --shard $i/2 --out-dir s$i >/dev/null 2>&1; done
"$scw" merge s1 s0 --out-dir merged
test "$(ls s0)" = "$(printf 'seed_1.json\nshard.json')" || { echo "FAIL: shard 0/2 is not seed 1"; exit 1; }
diff <(ls one) <(ls merged) || { echo "FAIL: other files"; exit 1; }
test "$(ls merged | wc -l)" -eq 3
without_seconds() { sed '/"seconds": {/,/}/d' "$1"; }
for f in one/*.json; do
  diff <(without_seconds "$f") <(without_seconds "merged/${f#one/}") ||
    { echo "FAIL: ${f#one/} differs beyond the wall-clock seconds"; exit 1; }
  grep -q '"passed": true' "$f" || { echo "FAIL: $f did not pass"; exit 1; }
done
echo "soak --seeds 3: 2 shards merged == one process (wall-clock seconds aside)"
