#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Reruns every test that simulates Verilated RTL with its unreset registers, memories and explicit
# Xs random, once per seed (docs/rtl.md, "X and reset"). CI runs seed 1 (the "x-seed1 ..." tests);
# this runs more.
#   scripts/x_seeds.sh [--build DIR] SEED...      e.g. scripts/x_seeds.sh 2 3 4 5
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="$root/build" seeds=()
while [ $# -gt 0 ]; do
  case "$1" in
    --build) build="$2"; shift 2 ;;
    -h|--help) sed -n '3,7p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) [[ "$1" =~ ^[1-9][0-9]*$ ]] ||
         { echo "x_seeds.sh: '$1' is not a seed: give whole numbers from 1, e.g. 2 3 4" >&2; exit 2; }
       seeds+=("$1"); shift ;;
  esac
done
[ ${#seeds[@]} -gt 0 ] || { echo "x_seeds.sh: give at least one seed, e.g. 2 3 4" >&2; exit 2; }
[ -f "$build/CTestTestfile.cmake" ] ||
  { echo "x_seeds.sh: '$build' is not a built scw (run scripts/build.sh, or give --build DIR)" >&2; exit 2; }
for s in "${seeds[@]}"; do
  echo "x_seeds: seed $s"
  # The x-seed1 tests are the same tests with the seed fixed to 1: run the plain ones, which read
  # the seed from the environment.
  SCW_VERILATOR_SEED="$s" ctest --test-dir "$build" -j "${SCW_JOBS:-$(nproc)}" \
    -LE "lint|yosys|fuzz|install|^x$" --output-on-failure
done
