#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The main job on the bundled data: installs what is missing, builds, and streams the Tsukuba
# left image through the Verilated line buffer in the cycle simulator (3 frames, P = 2),
# checking every beat and writing out/stream/report.json and a golden vector set; then
# rectifies a raw chessboard pair through the fixed-point rectify stage (out/rectify/); then
# computes Tsukuba's disparity through the disparity model (out/disparity/) and segments it into
# objects through the tiled labelling model, with the host's post-processing (out/segment/);
# the whole chain with the warning stage and its overlay (out/run/); last, the whole pipeline
# clocked cycle by cycle, frame period and latency beside the thesis's (out/sim/); and a short
# synthetic distance sweep rendered through a distorted rig, run raw through the whole chain and
# scored against its truth (out/scene/).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
"$root/scripts/build.sh" --target scw
cd "$root"
./build/host/cli/scw stream --image data/tsukuba/scene1.row3.col3.ppm --ppc 2 --engine rtl \
  --frames 3 --out-dir out/stream "$@"
./build/host/cli/scw vectors verify out/stream/vectors
./build/host/cli/scw rectify --calib data/chessboard/derived_stereo_calibration_helper.yml \
  --left data/chessboard/left01.jpg --right data/chessboard/right01.jpg --out-dir out/rectify
mkdir -p out/disparity
./build/host/cli/scw disparity --left data/tsukuba/scene1.row3.col3.ppm \
  --right data/tsukuba/scene1.row3.col4.ppm --window 9 --min-disp 0 --max-disp 15 \
  --out out/disparity/disparity.png --out16 out/disparity/disparity16.png \
  --color out/disparity/disparity_color.png
./build/host/cli/scw segment --disparity out/disparity/disparity16.png --min-area 50 --tiles 4x3 \
  --post --out-dir out/segment
# Tsukuba's camera is not published with the pair: f 615 px and b 0.1 m are assumed.
./build/host/cli/scw run --rectified --focal 615 --baseline 0.1 --window 9 --min-disp 0 \
  --max-disp 15 --min-area 50 --left data/tsukuba/scene1.row3.col3.ppm \
  --right data/tsukuba/scene1.row3.col4.ppm --out-dir out/run
# The whole pipeline clocked at the thesis size (C++ models; -DSCW_THESIS_RTL=ON for all RTL),
# beside the thesis's Table 5.7, and at the small size with every block Verilated.
mkdir -p out/sim
./build/host/cli/scw sim --config thesis --ppc 1 --frames 3 --engine cpp --json out/sim/thesis_p1.json
./build/host/cli/scw sim --config thesis --ppc 4 --frames 3 --engine cpp --json out/sim/thesis_p4.json
./build/host/cli/scw sim --config small --ppc 1 --frames 3 --engine rtl --json out/sim/small_rtl.json
# Five poses of the distance sweep (30 .. 6 m; the full 49 are docs/scene.md's), rendered raw,
# rectified and run at the thesis size, scored against the truth: table, plots, eval.json.
./build/host/cli/scw scene --preset distance-sweep --frames 5 --out-dir out/scene
./build/host/cli/scw run --calib out/scene/calibration.yml --sequence out/scene --min-disp 12 \
  --max-disp 56 --window 21 --tiles 8x4 --camera-height 1.2 --out-dir out/scene/run
./build/host/cli/scw eval --truth out/scene --results out/scene/run/results.jsonl \
  --json out/scene/run/eval.json
