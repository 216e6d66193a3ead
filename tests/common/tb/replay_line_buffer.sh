#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Builds tb_line_buffer_replay.sv with Verilator (--binary) and replays a line_buffer vector
# set: the route a user takes with their own simulator. Usage: replay_line_buffer.sh SET WORKDIR
set -euo pipefail
set_dir="$(cd "${1:?vector set folder}" && pwd)"
work="${2:?work folder}"
root="$(cd "$(dirname "$0")/../../.." && pwd)"
field() { grep -o "\"$1\": *[0-9]*" "$set_dir/manifest.json" | head -1 | grep -o '[0-9]*$'; }
ppc=$(field ppc); rows=$(field rows); width=$(field max_width_px); beats=$(field beats)
mkdir -p "$work"
verilator --binary --timing -Wno-fatal -Wno-lint -Wno-style --top-module tb_line_buffer_replay \
  -GPpc="$ppc" -GMaxWidthPx="$width" -GRows="$rows" -GBeats="$beats" \
  "$root/rtl_models/common/scw_pkg.sv" "$root/rtl_models/common/scw_ram_sdp.sv" \
  "$root/rtl_models/common/scw_line_buffer.sv" "$root/tests/common/tb/tb_line_buffer_replay.sv" \
  -Mdir "$work/obj" >"$work/build.log" 2>&1 || { cat "$work/build.log"; exit 1; }
"$work/obj/Vtb_line_buffer_replay" +vectors="$set_dir"
