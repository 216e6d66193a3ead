#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Submits an scw command as a Slurm job array of N shards (--shard I/N, I = SLURM_ARRAY_TASK_ID)
# and `scw merge` as a job that starts when every shard has succeeded (docs/slurm.md):
#
#   scripts/slurm_run.sh -n 4 -o out/sweep -- run --calib seq/calibration.yml --sequence seq
#
# Shard I writes DIR.shards/I (and its log DIR.shards/slurm-JOB_I.out); the merge writes DIR,
# exactly what one process would have written. Prints the two job ids ("array 12 merge 13").
# Paths are taken from the folder this is run in (the jobs start there: give a shared folder on a
# real cluster). A failed shard cancels the merge (--kill-on-invalid-dep).
set -euo pipefail

usage() {
  cat <<USAGE
usage: $0 [-n N] -o DIR [--scw PATH] [--out-option OPT] [--sbatch ARG]... -- COMMAND [ARGS]...
  -n N            shards (default 4)
  -o DIR          the merged output folder; the shards write DIR.shards/0 .. DIR.shards/N-1
  --scw PATH      the scw to run (default: this checkout's build/host/cli/scw, else scw on PATH)
  --out-option O  the option COMMAND takes its output folder with (default --out-dir)
  --sbatch ARG    passed to both sbatch calls (repeat it), e.g. --sbatch --partition=short
  COMMAND ARGS    an scw command that takes --shard, and its options, without --shard and the
                  output folder: run ... (frames) or soak --seeds K ... (seeds)
USAGE
  exit 2
}

root="$(cd "$(dirname "$0")/.." && pwd)"
n=4 out="" out_option=--out-dir sbatch_args=()
scw="$root/build/host/cli/scw"
[ -x "$scw" ] || scw="$(command -v scw || true)"
while [ $# -gt 0 ]; do
  case "$1" in
    -n) n="$2"; shift 2 ;;
    -o) out="$2"; shift 2 ;;
    --scw) scw="$2"; shift 2 ;;
    --out-option) out_option="$2"; shift 2 ;;
    --sbatch) sbatch_args+=("$2"); shift 2 ;;
    --) shift; break ;;
    *) usage ;;
  esac
done
if [ -z "$out" ] || [ $# -eq 0 ]; then usage; fi
[[ "$n" =~ ^[1-9][0-9]*$ ]] || { echo "$0: -n $n: give a whole number of shards, e.g. 4" >&2; exit 2; }
[ -x "$scw" ] || { echo "$0: no scw found: build it (scripts/build.sh) or give --scw PATH" >&2; exit 2; }
command -v sbatch >/dev/null || { echo "$0: sbatch not found: run this where Slurm's client commands are" >&2; exit 2; }

scw="$(cd "$(dirname "$scw")" && pwd)/$(basename "$scw")"
shards="$out.shards"
mkdir -p "$shards"
# The jobs' command lines, every word quoted for the job's shell; the task id is expanded there.
printf -v run '%q ' "$scw" "$@" "$out_option"
run="exec $run$(printf %q "$shards")/\$SLURM_ARRAY_TASK_ID --shard \$SLURM_ARRAY_TASK_ID/$n"
merge="exec $(printf '%q ' "$scw" merge --out-dir "$out")"
for ((i = 0; i < n; i++)); do merge+=" $(printf %q "$shards/$i")"; done

array=$(sbatch --parsable --chdir="$PWD" --array=0-$((n - 1)) --job-name="scw-$1" \
  --output="$shards/slurm-%A_%a.out" "${sbatch_args[@]}" --wrap="$run")
array=${array%%;*}
merge_job=$(sbatch --parsable --chdir="$PWD" --dependency=afterok:"$array" --kill-on-invalid-dep=yes \
  --job-name="scw-merge" --output="$shards/slurm-merge-%j.out" "${sbatch_args[@]}" --wrap="$merge")
merge_job=${merge_job%%;*}
echo "array $array merge $merge_job"
