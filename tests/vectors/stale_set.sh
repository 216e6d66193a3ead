#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# A set whose words are not the RTL's width (made before a width in scw_pkg.sv changed) must be
# refused by name in both simulators, before any word is compared:
#   stale_set.sh SET FILE WORKDIR    FILE: the set's file whose words must be the RTL's width
# The copy's manifest gives FILE's words 64 bits more: any width but the RTL's would do, and 64
# more stays clear of the RTL's own when a field of the package is narrowed.
set -euo pipefail
set_dir="$1" file="$2" work="$3"
root="$(cd "$(dirname "$0")/../.." && pwd)"
rm -rf "$work" && mkdir -p "$work"
cp -r "$set_dir" "$work/set"
awk -v name="\"name\": \"$file\"" '
  index($0, name) { f = 1 }
  f && /"width_bits":/ { match($0, /[0-9]+/); w = substr($0, RSTART, RLENGTH); sub(/[0-9]+/, w + 64); f = 0 }
  { print }' "$set_dir/manifest.json" >"$work/set/manifest.json"
if cmp -s "$set_dir/manifest.json" "$work/set/manifest.json"; then
  echo "stale_set.sh: no width_bits for $file in $set_dir/manifest.json" >&2
  exit 1
fi
for sim in verilator icarus; do
  if bash "$root/scripts/replay.sh" "$work/set" "$work/$sim" --simulator "$sim" >"$work/$sim.log" 2>&1; then
    echo "stale_set.sh: $sim replayed a set whose $file words are 64 bits wider" >&2
    exit 1
  fi
  if ! grep -q "the set was made at other scw_pkg widths" "$work/$sim.log"; then
    echo "stale_set.sh: $sim failed without naming the widths:" >&2
    tail -5 "$work/$sim.log" >&2
    exit 1
  fi
  grep -m1 "the set was made at other scw_pkg widths" "$work/$sim.log"
done
