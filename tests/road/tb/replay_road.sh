#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Builds tb_road_replay.sv with Verilator (--binary) and replays a road vector set: the route a
# user takes with their own simulator. Usage: replay_road.sh SET WORKDIR [PLUSARG ...]
# (extra plusargs go to the testbench, e.g. +stalls=0).
set -euo pipefail
set_dir="$(cd "${1:?vector set folder}" && pwd)"
work="${2:?work folder}"
shift 2
root="$(cd "$(dirname "$0")/../../.." && pwd)"
# A value of the manifest's config block by key: an integer (nominal_b is negative) or a boolean
# (true/false -> 1/0). The config comes before the file table, so the first match is the
# config's even for keys the file entries repeat (width, height, beats).
field() {
  local v
  v="$(grep -o "\"$1\": *[-a-z0-9]*" "$set_dir/manifest.json" | head -1 | sed 's/.*: *//' |
    sed 's/^true$/1/; s/^false$/0/')"
  [ -n "$v" ] || { echo "replay_road.sh: no '$1' in $set_dir/manifest.json" >&2; exit 1; }
  echo "$v"
}
mkdir -p "$work"
common=("$root/rtl_models/common/scw_pkg.sv")
for f in "$root"/rtl_models/common/*.sv; do
  [ "$f" = "$root/rtl_models/common/scw_pkg.sv" ] || common+=("$f")
done
params=()
for kv in Ppc=ppc MaxWidthPx=max_width_px MaxHeight=max_height Beats=beats Frames=frames \
  FitClocks=fit_clocks; do
  params+=("-G${kv%%=*}=$(field "${kv#*=}")")
done
verilator --binary --timing -Wno-fatal -Wno-lint -Wno-style --top-module tb_road_replay \
  "${params[@]}" \
  "${common[@]}" "$root"/rtl_models/road/*.sv "$root/tests/road/tb/tb_road_replay.sv" \
  -Mdir "$work/obj" >"$work/build.log" 2>&1 || { cat "$work/build.log"; exit 1; }
args=(+vectors="$set_dir")
for key in width height enable nominal_a nominal_b a_min a_max h_min h_max tol_q4 tol_rel_q8 \
  gate_q4 gate_rel_q8 min_count; do
  args+=("+$key=$(field "$key")")
done
"$work/obj/Vtb_road_replay" "${args[@]}" "$@"
