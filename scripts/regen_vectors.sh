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
