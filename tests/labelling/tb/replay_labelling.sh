#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Builds tb_labelling_replay.sv with Verilator (--binary) and replays a labelling vector set: the
# route a user takes with their own simulator. Usage: replay_labelling.sh SET WORKDIR
set -euo pipefail
set_dir="$(cd "${1:?vector set folder}" && pwd)"
work="${2:?work folder}"
root="$(cd "$(dirname "$0")/../../.." && pwd)"
# A number from the manifest's config block (written before the file table, so the first match
# is the config's even for keys the image entries repeat, such as width).
field() { grep -o "\"$1\": *[0-9]*" "$set_dir/manifest.json" | head -1 | grep -o '[0-9]*$'; }
mkdir -p "$work"
verilator --binary --timing -Wno-fatal -Wno-lint -Wno-style --top-module tb_labelling_replay \
  -GMaxWidthPx="$(field max_width_px)" -GMaxHeight="$(field max_height)" \
  -GMaxTilesX="$(field max_tiles_x)" -GMaxTilesY="$(field max_tiles_y)" \
  -GLabelsPerTile="$(field labels_per_tile)" -GMaxObjects="$(field max_objects)" \
  -GBeatsIn="$(field beats_in)" -GWordsOut="$(field words_out)" -GFrames="$(field frames)" \
  "$root/rtl_models/common/scw_pkg.sv" "$root/rtl_models/common/scw_ram_sdp.sv" \
  "$root/rtl_models/common/scw_fifo.sv" \
  "$root"/rtl_models/labelling/*.sv "$root/tests/labelling/tb/tb_labelling_replay.sv" \
  -Mdir "$work/obj" >"$work/build.log" 2>&1 || { cat "$work/build.log"; exit 1; }
"$work/obj/Vtb_labelling_replay" +vectors="$set_dir" +width="$(field width)" \
  +height="$(field height)" +tile_w="$(field tile_w)" +tile_h="$(field tile_h)" \
  +floor="$(field floor)" +min_area="$(field min_area)"
