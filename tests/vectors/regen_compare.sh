#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Regenerates every committed golden vector set into OUT (scripts/regen_vectors.sh) and compares
# each with the committed one (`scw vectors compare`): the same sets and files, each file equal
# byte for byte, or, where a word's layout changed (a field of scw_pkg.sv made wider or narrower
# since the set was committed), every field of every beat equal in value. The regenerated sets are
# what the replay tests then run (tests/vectors/replay.cmake), so the RTL of this build is
# replayed at its own packing. A repacked file is named, with the command that rewrites the
# committed sets (docs/vectors.md, "When a width changes").
#   regen_compare.sh SCW OUT
set -euo pipefail
scw="$1" out="$2"
root="$(cd "$(dirname "$0")/../.." && pwd)"
rm -rf "$out"
bash "$root/scripts/regen_vectors.sh" "$scw" "$out"
diff <(cd "$root/vectors" && find . -type f ! -name README.md | sort) <(cd "$out" && find . -type f | sort) ||
  { echo "FAIL: the regenerated sets hold other files than the committed ones (above)"; exit 1; }
repacked=0
while read -r manifest; do
  set_dir="$(dirname "$manifest")"
  result="$("$scw" vectors compare "$root/vectors/$set_dir" "$out/$set_dir" 2>&1)" ||
    { echo "$result"; echo "FAIL: $set_dir does not regenerate"; exit 1; }
  echo "$result"
  if [[ $result == *"at another packing"* ]]; then repacked=$((repacked + 1)); fi
done < <(cd "$root/vectors" && find . -name manifest.json | sed "s|^\./||" | sort)
if [ "$repacked" -gt 0 ]; then
  echo "NOTE: $repacked committed sets hold the same values at another packing; run"
  echo "      scripts/regen_vectors.sh build/host/cli/scw to rewrite them"
fi
