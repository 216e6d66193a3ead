#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Installs what scw needs from Debian's packages, only if something is missing (fast otherwise).
set -euo pipefail

# cmake/g++/make/ninja: build; verilator + zlib1g-dev: RTL simulation with FST traces;
# yosys: synthesis checks; iverilog: the 4-state replay of vector sets (scripts/replay.sh);
# libopencv-dev, libeigen3-dev: references and image I/O;
# catch2, libcli11-dev, nlohmann-json3-dev: tests, CLI, manifests; libssl-dev: SHA-256 of
# golden vectors (OpenSSL's EVP, not a hand-written hash); git: cloning and CI; clang and its
# runtime libraries (libFuzzer, AddressSanitizer; only recommended by clang, so named): fuzzing
# the file parsers (scripts/fuzz.sh); slurm-wlm (slurmctld, slurmd, the client commands) and
# munge (its authentication): the test that starts a one-node Slurm cluster and runs a sharded
# job through it (docs/slurm.md); parallel: GNU parallel, the one-workstation way to run shards;
# libjemalloc2: the allocator Yosys runs with, about 27 % faster (scripts/synth_flow.sh).
packages=(cmake g++ make ninja-build pkg-config git verilator zlib1g-dev yosys libjemalloc2 iverilog
          libopencv-dev libeigen3-dev catch2 libcli11-dev nlohmann-json3-dev libssl-dev clang libclang-rt-14-dev
          slurm-wlm munge parallel)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

echo "scw: installing missing Debian packages: ${missing[*]}"
sudo=""
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null; then sudo="sudo"; else
    echo "scw: need root (or sudo) to install: ${missing[*]}" >&2
    exit 1
  fi
fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -q
$sudo apt-get install -y -q --no-install-recommends "${missing[@]}"
