#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Builds tb_disparity_replay.sv with Verilator (--binary) and replays a disparity vector set: the
# route a user takes with their own simulator. Usage: replay_disparity.sh SET WORKDIR
set -euo pipefail
set_dir="$(cd "${1:?vector set folder}" && pwd)"
work="${2:?work folder}"
root="$(cd "$(dirname "$0")/../../.." && pwd)"
# The manifest's config block: numbers and booleans (true/false -> 1/0) by key.
field() {
  grep -o "\"$1\": *[a-z0-9]*" "$set_dir/manifest.json" | head -1 | sed 's/.*: *//' |
    sed 's/^true$/1/; s/^false$/0/'
}
ppc=$(field ppc); max_w=$(field max_width_px); max_h=$(field max_height)
window=$(field window); built=$(field num_disp); beats=$(field beats)
mkdir -p "$work"
verilator --binary --timing -Wno-fatal -Wno-lint -Wno-style --top-module tb_disparity_replay \
  -GPpc="$ppc" -GMaxWidthPx="$max_w" -GMaxHeight="$max_h" -GWindow="$window" \
  -GNumDisp="$built" -GBeats="$beats" \
  "$root/rtl_models/common/scw_pkg.sv" "$root/rtl_models/common/scw_ram_sdp.sv" \
  "$root"/rtl_models/disparity/*.sv "$root/tests/disparity/tb/tb_disparity_replay.sv" \
  -Mdir "$work/obj" >"$work/build.log" 2>&1 || { cat "$work/build.log"; exit 1; }
"$work/obj/Vtb_disparity_replay" +vectors="$set_dir" +width="$(field width)" \
  +height="$(field height)" +dmin="$(field dmin)" +num_disp="$(field num_disp)" \
  +prefilter="$(field prefilter)" +cap="$(field prefilter_cap)" +sad_limit="$(field sad_limit)" \
  +texture="$(field texture_threshold)" +uniqueness="$(field uniqueness_ratio)" \
  +subpixel="$(field subpixel)" +opencv_invalid="$(field opencv_invalid)" \
  +edge="$(field edge_candidates)"
