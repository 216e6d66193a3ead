#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Regenerates every committed golden vector set. Usage: regen_vectors.sh SCW_BINARY [OUT_ROOT]
# OUT_ROOT defaults to the repository's vectors/; CTest regenerates into a scratch folder and
# compares it byte for byte with the committed sets.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
scw="${1:?usage: regen_vectors.sh SCW_BINARY [OUT_ROOT]}"
out="${2:-$root/vectors}"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT

# put_set FROM DEST: the set a command wrote in the scratch folder FROM, at $out/DEST (replaced).
put_set() {
  mkdir -p "$(dirname "$out/$2")"
  rm -rf "${out:?}/$2"
  cp -r "$1" "$out/$2"
}
# `scw vectors STAGE --preset PRESET ARGS...` into $out/STAGE/PRESET.
preset_set() {
  local stage="$1" preset="$2"
  shift 2
  "$scw" vectors "$stage" --preset "$preset" "$@" --out "$tmp/${stage}_$preset" >/dev/null
  put_set "$tmp/${stage}_$preset" "$stage/$preset"
}

# common/line_buffer: a 64 x 16 crop of Tsukuba through the Verilated line buffer, P = 2.
"$scw" stream --image "$root/data/tsukuba/scene1.row3.col3.ppm" --roi 160 120 64 16 --ppc 2 \
  --engine rtl --frames 1 --out-dir "$tmp/line_buffer" >/dev/null
put_set "$tmp/line_buffer/vectors" common/line_buffer

# rectify/<preset>: 64 x 32 test card shifted, rotated, barrel-undistorted, and a 128 x 96 crop
# of each bundled chessboard image rectified with the real calibration; the Verilated
# scw_rectify (P = 2) makes them, checked against the C++ model and the integer reference.
for preset in shift rotation barrel chessboard_left chessboard_right; do
  preset_set rectify "$preset" --ppc 2 --engine rtl --data-dir "$root/data/chessboard"
done

# disparity/<preset>: a 64 x 24 random texture pair with known shifts (N = 5, d 0..15, thesis
# mode), a 96 x 48 Tsukuba crop (N = 9, d 0..15, opencv mode) and the same crop with the left
# edge band (edge_candidates 4), P = 2, from the C++ model, checked against the direct
# reference; CTest replays each against scw_disparity (tests/disparity/tb/).
for preset in texture tsukuba tsukuba_edge; do
  preset_set disparity "$preset" --data-dir "$root/data/tsukuba"
done

# labelling/<preset>: five 64 x 48 adversarial shapes through one stage on 3 x 4 uneven tiles, a
# 64 x 48 crop of the Tsukuba ground truth (2 x 2 tiles, min area 4), and a tile overflow and an
# object overflow followed by a normal frame; from the C++ model of the stage built for 64 x 48,
# 4 x 4 tiles of 64 labels, 64 objects, checked against the flood-fill reference; CTest replays
# them against scw_labelling (tests/labelling/tb/).
for preset in shapes tsukuba overflow; do
  preset_set labelling "$preset" --data-dir "$root/data/tsukuba"
done

# warning/<preset>: hand-placed objects for each rule of eq. 5.2 (incl. the thesis's worked
# example), 64 seeded random tables, and broken tables each followed by a good one; from the C++
# model of the stage built with MaxDisparityPx = 128, checked against a plain fold of evaluate();
# CTest replays them against scw_warning (tests/warning/tb/).
for preset in thesis random malformed; do preset_set warning "$preset"; done

# road/<preset>: six 64 x 48 synthetic road maps whose road the stage finds from a wrong nominal
# and follows as the horizon pitches, and five maps whose fits the plausibility rules refuse (the
# road stays the nominal); from the C++ model of the stage built with P = 2, 64 x 48, checked
# against the floating-point reference; CTest replays them against scw_road (tests/road/tb/).
for preset in street implausible; do preset_set road "$preset"; done

# pipeline/small_street: the whole scw_pipeline top at the small build (P = 1), three 64 x 32
# synthetic street frames back to back, raw pairs and knots in, every stream between the stages
# and the frame results out; from the C++ chain, checked against the Verilated top; CTest
# replays it in Verilator and Icarus (tests/pipeline/tb/).
"$scw" vectors pipeline --config small --frames 3 --out "$tmp/pipeline_small_street" >/dev/null
put_set "$tmp/pipeline_small_street" pipeline/small_street
