#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Fuzzes every file parser with libFuzzer (clang, AddressSanitizer, UBSan): docs/fuzz.md.
#   scripts/fuzz.sh [--seconds N] [--build DIR] [--jobs J] [TARGET...]
# Configures a clang build of the fuzz targets in DIR (default build-fuzz), then runs each
# target (default: all) for N seconds (default 60) from a copy of its seed corpus in
# fuzz/corpus/TARGET. An input that crashes, trips a sanitizer or draws an error that is not
# scw's own is written to DIR/findings/TARGET/ and the script fails naming it; keep it in
# fuzz/regressions/TARGET/ once fixed, and ctest replays it from then on.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
seconds=60 build="$root/build-fuzz" jobs="${SCW_JOBS:-$(nproc)}" targets=()
while [ $# -gt 0 ]; do
  case "$1" in
    --seconds) seconds="$2"; shift 2 ;;
    --build) build="$2"; shift 2 ;;
    --jobs) jobs="$2"; shift 2 ;;
    -h|--help) sed -n '3,9p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) echo "fuzz.sh: unknown option '$1' (--seconds N, --build DIR, --jobs J)" >&2; exit 2 ;;
    *) targets+=("$1"); shift ;;
  esac
done
if ! [[ "$seconds" =~ ^[1-9][0-9]*$ ]]; then
  echo "fuzz.sh: --seconds '$seconds' is not a whole number of seconds >= 1, e.g. --seconds 60" >&2
  exit 2
fi
if ! command -v clang++ >/dev/null; then
  echo "fuzz.sh: clang++ is missing: apt-get install clang libclang-rt-14-dev (scripts/deps.sh)" >&2
  exit 1
fi
all=$(sed -n 's/^set(SCW_FUZZ_TARGETS \(.*\))$/\1/p' "$root/fuzz/CMakeLists.txt")
[ ${#targets[@]} -gt 0 ] || read -r -a targets <<< "$all"
for t in "${targets[@]}"; do
  [[ " $all " == *" $t "* ]] || { echo "fuzz.sh: no target '$t'; there are: $all" >&2; exit 2; }
done

mkdir -p "$(dirname "$build")"  # its configure log goes beside it
CC=clang CXX=clang++ cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DSCW_FUZZ=ON -DBUILD_TESTING=OFF > "$build.configure.log" 2>&1 ||
  { cat "$build.configure.log" >&2; exit 1; }
cmake --build "$build" -j "$jobs" --target "${targets[@]/#/fuzz_}"

# An input OpenCV's reader loops on costs the reader's whole time limit (host/io/file_storage.hpp):
# 1 s, not a user's 5, leaves the fuzzer more of its time.
export SCW_READER_SECONDS="${SCW_READER_SECONDS:-1}"
failed=()
for t in "${targets[@]}"; do
  work="$build/corpus/$t" findings="$build/findings/$t"
  rm -rf "$work" "$findings" && mkdir -p "$work" "$findings"
  cp "$root/fuzz/corpus/$t"/* "$work/"
  echo "fuzz: $t for ${seconds} s"
  # The first folder is the working corpus libFuzzer adds to; the committed seeds stay as they are.
  if ! "$build/fuzz/fuzz_$t" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
       -print_final_stats=1 -artifact_prefix="$findings/" "$work" \
       > "$build/findings/$t.log" 2>&1; then
    failed+=("$t")
    echo "fuzz: $t found an input: $(ls "$findings" | head -1) (log: $build/findings/$t.log)" >&2
    grep -m3 -E "ERROR|not a clear error|runtime error" "$build/findings/$t.log" >&2 || true
  fi
  grep -E "^stat::number_of_executed_units|^stat::new_units_added" "$build/findings/$t.log" |
    sed "s/^/fuzz: $t: /"
done
if [ ${#failed[@]} -gt 0 ]; then
  echo "fuzz: findings in ${failed[*]} (inputs under $build/findings/)" >&2
  exit 1
fi
echo "fuzz: ${#targets[@]} targets, ${seconds} s each, nothing found"
