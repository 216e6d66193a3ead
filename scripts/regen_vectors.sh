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

# common/line_buffer: a 64 x 16 crop of Tsukuba through the Verilated line buffer, P = 2.
"$scw" stream --image "$root/data/tsukuba/scene1.row3.col3.ppm" --roi 160 120 64 16 --ppc 2 \
  --engine rtl --frames 1 --out-dir "$tmp/line_buffer" >/dev/null
mkdir -p "$out/common"
rm -rf "$out/common/line_buffer"
cp -r "$tmp/line_buffer/vectors" "$out/common/line_buffer"

# rectify/<preset>: 64 x 32 test card shifted, rotated, barrel-undistorted, and a 128 x 96 crop
# of each bundled chessboard image rectified with the real calibration; the Verilated
# scw_rectify (P = 2) makes them, checked against the C++ model and the integer reference.
mkdir -p "$out/rectify"
for preset in shift rotation barrel chessboard_left chessboard_right; do
  "$scw" vectors rectify --preset "$preset" --ppc 2 --engine rtl \
    --data-dir "$root/data/chessboard" --out "$tmp/rectify_$preset" >/dev/null
  rm -rf "$out/rectify/$preset"
  cp -r "$tmp/rectify_$preset" "$out/rectify/$preset"
done

# disparity/<preset>: a 64 x 24 random texture pair with known shifts (N = 5, d 0..15, thesis
# mode), a 96 x 48 Tsukuba crop (N = 9, d 0..15, opencv mode) and the same crop with the left
# edge band (edge_candidates 4), P = 2, from the C++ model, checked against the direct
# reference; CTest replays each against scw_disparity (tests/disparity/tb/).
mkdir -p "$out/disparity"
for preset in texture tsukuba tsukuba_edge; do
  "$scw" vectors disparity --preset "$preset" --data-dir "$root/data/tsukuba" \
    --out "$tmp/disparity_$preset" >/dev/null
  rm -rf "$out/disparity/$preset"
  cp -r "$tmp/disparity_$preset" "$out/disparity/$preset"
done

# labelling/<preset>: five 64 x 48 adversarial shapes through one stage on 3 x 4 uneven tiles, a
# 64 x 48 crop of the Tsukuba ground truth (2 x 2 tiles, min area 4), and a tile overflow and an
# object overflow followed by a normal frame; from the C++ model of the stage built for 64 x 48,
# 4 x 4 tiles of 64 labels, 64 objects, checked against the flood-fill reference; CTest replays
# them against scw_labelling (tests/labelling/tb/).
mkdir -p "$out/labelling"
for preset in shapes tsukuba overflow; do
  "$scw" vectors labelling --preset "$preset" --data-dir "$root/data/tsukuba" \
    --out "$tmp/labelling_$preset" >/dev/null
  rm -rf "$out/labelling/$preset"
  cp -r "$tmp/labelling_$preset" "$out/labelling/$preset"
done

# warning/<preset>: hand-placed objects for each rule of eq. 5.2 (incl. the thesis's worked
# example), 64 seeded random tables, and broken tables each followed by a good one; from the C++
# model of the stage built with MaxDisparityPx = 128, checked against a plain fold of evaluate();
# CTest replays them against scw_warning (tests/warning/tb/).
mkdir -p "$out/warning"
for preset in thesis random malformed; do
  "$scw" vectors warning --preset "$preset" --out "$tmp/warning_$preset" >/dev/null
  rm -rf "$out/warning/$preset"
  cp -r "$tmp/warning_$preset" "$out/warning/$preset"
done

# road/<preset>: six 64 x 48 synthetic road maps whose road the stage finds from a wrong nominal
# and follows as the horizon pitches, and five maps whose fits the plausibility rules refuse (the
# road stays the nominal); from the C++ model of the stage built with P = 2, 64 x 48, checked
# against the floating-point reference; CTest replays them against scw_road (tests/road/tb/).
mkdir -p "$out/road"
for preset in street implausible; do
  "$scw" vectors road --preset "$preset" --out "$tmp/road_$preset" >/dev/null
  rm -rf "$out/road/$preset"
  cp -r "$tmp/road_$preset" "$out/road/$preset"
done

# pipeline/small_street: the whole scw_pipeline top at the small build (P = 1), three 64 x 32
# synthetic street frames back to back, raw pairs and knots in, every stream between the stages
# and the frame results out; from the C++ chain, checked against the Verilated top; CTest
# replays it in Verilator and Icarus (tests/pipeline/tb/).
mkdir -p "$out/pipeline"
"$scw" vectors pipeline --config small --frames 3 --out "$tmp/pipeline_small_street" >/dev/null
rm -rf "$out/pipeline/small_street"
cp -r "$tmp/pipeline_small_street" "$out/pipeline/small_street"
