#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Builds tb_warning_replay.sv with Verilator (--binary) and replays a warning vector set: the route
# a user takes with their own simulator. Usage: replay_warning.sh SET WORKDIR
set -euo pipefail
set_dir="$(cd "${1:?vector set folder}" && pwd)"
work="${2:?work folder}"
root="$(cd "$(dirname "$0")/../../.." && pwd)"
# A number from the manifest's config block (written before the file table; every key below
# occurs once in it). Signed: the vehicle origin is negative.
field() {
  local v
  v="$(grep -o "\"$1\": *-\?[0-9]*" "$set_dir/manifest.json" | head -1 | grep -o -- '-\?[0-9]*$')"
  [[ -n "$v" ]] || { echo "replay_warning: no '$1' in $set_dir/manifest.json" >&2; exit 1; }
  echo "$v"
}
cfg=()
for k in baseline_q8 focal_q4 cu_q4 cv_q4 veh_x_mm veh_y_mm veh_z_mm tunnel_half_w_mm \
         tunnel_h_mm high_mm medium_mm near_mm min_height_mm d_limit_q4 rule spread_q4; do
  cfg+=("+$k=$(field "$k")")
done
mkdir -p "$work"
verilator --binary --timing -Wno-fatal -Wno-lint -Wno-style --top-module tb_warning_replay \
  -GMaxDisparityPx="$(field max_disparity_px)" -GWordsIn="$(field words_in)" \
  -GWordsOut="$(field words_out)" \
  "$root/rtl_models/common/scw_pkg.sv" "$root"/rtl_models/warning/*.sv \
  "$root/tests/warning/tb/tb_warning_replay.sv" \
  -Mdir "$work/obj" >"$work/build.log" 2>&1 || { cat "$work/build.log"; exit 1; }
"$work/obj/Vtb_warning_replay" +vectors="$set_dir" "${cfg[@]}" "${@:3}"
