#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# A replay must fail on a wrong expected beat and say where it is: copies a pipeline set, changes
# the disparity beat of frame 1, row 10, column 20, and requires scripts/replay.sh to fail in
# both simulators naming that stream, frame, row and column.
#   wrong_beat.sh SET WORKDIR
set -euo pipefail
set_dir="${1:?pipeline vector set}"
work="${2:?work folder}"
root="$(cd "$(dirname "$0")/../../.." && pwd)"
width="$(grep -o '"width": *[0-9]*' "$set_dir/manifest.json" | head -1 | grep -o '[0-9]*$')"
height="$(grep -o '"height": *[0-9]*' "$set_dir/manifest.json" | head -1 | grep -o '[0-9]*$')"
ppc="$(grep -o '"ppc": *[0-9]*' "$set_dir/manifest.json" | head -1 | grep -o '[0-9]*$')"
frame=1 row=10 column=20
line=$(( frame * (width / ppc) * height + row * (width / ppc) + column / ppc + 1 ))
rm -rf "$work" && mkdir -p "$work" && cp -r "$set_dir" "$work/set"
# Flip the lowest bit of the beat's last hex digit (a disparity bit).
awk -v n="$line" 'NR == n {
    d = substr($0, length($0), 1)
    $0 = substr($0, 1, length($0) - 1) substr("1032547698badcfe", index("0123456789abcdef", d), 1)
  } { print }' "$set_dir/disparity.hex" > "$work/set/disparity.hex"
want="disparity: beat $(( line - 1 )) (frame $frame, row $row, column $column)"
for sim in verilator icarus; do
  if bash "$root/scripts/replay.sh" "$work/set" "$work/$sim" --simulator "$sim" > "$work/$sim.log" 2>&1; then
    echo "FAIL: $sim replayed a set with a wrong beat without failing"; exit 1
  fi
  grep -F "$want" "$work/$sim.log" > /dev/null ||
    { cat "$work/$sim.log"; echo "FAIL: $sim did not say '$want'"; exit 1; }
  echo "$sim: $(grep -F "$want" "$work/$sim.log" | head -1 | sed 's/^.*disparity:/disparity:/')"
done
echo "PASS: both simulators stop at the wrong beat and name it"
