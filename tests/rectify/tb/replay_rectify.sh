#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Builds tb_rectify_replay.sv with Verilator (--binary) and replays a rectify vector set: the
# route a user takes with their own simulator. Usage: replay_rectify.sh SET WORKDIR
set -euo pipefail
set_dir="$(cd "${1:?vector set folder}" && pwd)"
work="${2:?work folder}"
root="$(cd "$(dirname "$0")/../../.." && pwd)"
# The first match is the config block (the manifest writes config before files; every hex file
# of a set has the same number of beats).
field() { grep -o "\"$1\": *[0-9]*" "$set_dir/manifest.json" | head -1 | grep -o '[0-9]*$'; }
ppc=$(field ppc); width=$(field width); height=$(field height); lead=$(field lead_rows)
max_w=$(field max_width_px); max_h=$(field max_height); rows=$(field rows)
frac=$(field frac_bits); coord=$(field coord_bits); beats=$(field beats)
mkdir -p "$work"
verilator --binary --timing -Wno-fatal -Wno-lint -Wno-style --top-module tb_rectify_replay \
  -GPpc="$ppc" -GMaxWidthPx="$max_w" -GMaxHeight="$max_h" -GRows="$rows" -GFracBits="$frac" \
  -GCoordBits="$coord" -GBeats="$beats" \
  "$root/rtl_models/common/scw_pkg.sv" "$root/rtl_models/common/scw_ram_sdp.sv" \
  "$root/rtl_models/rectify/scw_rectify.sv" "$root/tests/rectify/tb/tb_rectify_replay.sv" \
  -Mdir "$work/obj" >"$work/build.log" 2>&1 || { cat "$work/build.log"; exit 1; }
"$work/obj/Vtb_rectify_replay" +vectors="$set_dir" +width="$width" +height="$height" +lead="$lead"
