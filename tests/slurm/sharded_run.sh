#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# A sharded `scw run` through a real Slurm (docs/slurm.md): starts a one-node cluster
# (one_node_cluster.sh), submits a short synthetic sequence as a 4-shard job array and its merge
# with scripts/slurm_run.sh, waits for both, and compares the merged folder with one process's
# run of the same sequence (--segments 4) file by file, byte for byte. Prints its own time.
# Fails, with the daemons' and jobs' logs, when the cluster cannot start, a job fails or a wait
# times out; the daemons are stopped on every exit.
# usage: sharded_run.sh SCW WORK_DIR
set -euo pipefail
scw=$1 work=$2
here="$(cd "$(dirname "$0")" && pwd)"
start=$SECONDS
rm -rf "$work" && mkdir -p "$work" && cd "$work"
source "$here/one_node_cluster.sh"
cluster_start "$work/cluster"
echo "cluster up in $((SECONDS - start)) s: $(sinfo -h -N -o '%N %T %c CPUs')"

"$scw" scene --preset cyclist-crossing --frames 9 --subsamples 1 --out-dir seq >/dev/null 2>&1
echo "scene made at $((SECONDS - start)) s"
run=(run --calib seq/calibration.yml --sequence seq --min-disp 12 --max-disp 56 --window 21
     --tiles 8x4 --pictures overlay)
jobs=$("$here/../../scripts/slurm_run.sh" -n 4 -o merged --scw "$scw" -- "${run[@]}")
echo "submitted: $jobs"

# No accounting daemon here (sacct), so the queue is watched: a merge that can never start (a shard
# failed) is cancelled by --kill-on-invalid-dep and leaves the queue too; the merged folder is
# the proof of success.
queue_empty() { [ -z "$(squeue -h 2>/dev/null)" ]; }
if ! cluster_wait 300 queue_empty; then
  squeue
  tail -n 20 merged.shards/*.out
  cluster_fail "jobs still queued after 300 s"
fi
if ! grep -q "^merged 4 shards" merged.shards/slurm-merge-*.out 2>/dev/null; then
  tail -n 20 merged.shards/*.out
  cluster_fail "the merge job did not run or failed"
fi
echo "jobs done at $((SECONDS - start)) s: $(cat merged.shards/slurm-merge-*.out)"

"$scw" "${run[@]}" --segments 4 --out-dir one >/dev/null 2>&1
echo "one process done at $((SECONDS - start)) s"
diff <(cd one && find . -type f | sort) <(cd merged && find . -type f | sort) ||
  { echo "FAIL: the merged folder holds other files than one process's"; exit 1; }
files=0
while read -r f; do
  cmp "one/$f" "merged/$f" || { echo "FAIL: $f differs"; exit 1; }
  files=$((files + 1))
done < <(cd one && find . -type f)
echo "4-shard Slurm job array merged == one process (--segments 4): $files files byte for byte," \
     "$(wc -l < merged/results.jsonl) frames; test time $((SECONDS - start)) s"
