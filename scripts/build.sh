#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Configures and builds scw in ./build (Release, Ninja); re-running only rebuilds what changed.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
"$root/scripts/deps.sh"
jobs="${SCW_JOBS:-$(nproc)}"
if [ ! -f "$root/build/build.ninja" ]; then
  cmake -S "$root" -B "$root/build" -G Ninja -DCMAKE_BUILD_TYPE=Release
fi
cmake --build "$root/build" -j "$jobs" "$@"
