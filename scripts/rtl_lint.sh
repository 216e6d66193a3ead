#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Lint one RTL module with Verilator -Wall; passes only with zero warnings (docs/rtl.md).
#
# Usage: scripts/rtl_lint.sh <module> [Param=value ...]
#        scripts/rtl_lint.sh --files <module>   (print the read list; used by rtl_synth.sh)
#
# Files read, in this order (paths relative to the repository root):
#   rtl_models/common/scw_pkg.sv, then every other package under rtl_models/,
#   every module file under rtl_models/common/, every module file beside <module>.sv.
# Every other folder holding modules is a library folder (verilator -y, yosys -libdir), so
# a top that instantiates another stage's module (the pipeline) still elaborates.
# Environment: VERILATOR (default: verilator on PATH).
set -euo pipefail

usage() {
  echo "usage: scripts/rtl_lint.sh <module> [Param=value ...] | --files <module>" >&2
  exit 2
}

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"

package_re='^[[:space:]]*package[[:space:]]+[A-Za-z_]'
# The files among "$@" that hold a package, one grep for all of them: a grep and a dirname per
# file were most of a lint's time (0.6 of 0.8 s), paid by every lint and every synthesis.
# grep's status 1 (no package among them) is not an error; 2 (a file it cannot read) is.
packages_among() { grep -lE "$package_re" "$@" || [[ $? -eq 1 ]]; }

# Prints "file <path>" and "libdir <dir>" lines for <module>, paths relative to the root.
list_files() {
  local module="$1" hits top_file stage_dir f d
  hits="$(find rtl_models -type f -name "${module}.sv" | LC_ALL=C sort)"
  if [[ -z "$hits" ]]; then
    echo "rtl_lint: no file rtl_models/**/${module}.sv (file name = module name)" >&2
    return 1
  fi
  if [[ "$(printf '%s\n' "$hits" | wc -l)" -ne 1 ]]; then
    echo "rtl_lint: module ${module} is defined by more than one file:" >&2
    printf '%s\n' "$hits" | sed 's/^/  /' >&2
    return 1
  fi
  top_file="$hits"
  stage_dir="${top_file%/*}"

  local -a all pkgs mods libdirs
  local -A is_pkg=()
  mapfile -t all < <(find rtl_models -type f -name '*.sv' | LC_ALL=C sort)
  while IFS= read -r f; do is_pkg["$f"]=1; done < <(packages_among "${all[@]}")
  if [[ -n "${is_pkg[$top_file]-}" ]]; then
    echo "rtl_lint: ${top_file} is a package, not a module" >&2
    return 1
  fi
  pkgs=()
  mods=()
  libdirs=()
  if [[ -f rtl_models/common/scw_pkg.sv ]]; then
    pkgs+=(rtl_models/common/scw_pkg.sv)
  fi
  for f in "${all[@]}"; do
    [[ "$f" == rtl_models/common/scw_pkg.sv ]] && continue
    if [[ -n "${is_pkg[$f]-}" ]]; then
      pkgs+=("$f")
    fi
  done
  for f in "${all[@]}"; do
    [[ -n "${is_pkg[$f]-}" ]] && continue
    d="${f%/*}"
    if [[ "$f" == rtl_models/common/* || "$d" == "$stage_dir" ]]; then
      mods+=("$f")
    elif [[ " ${libdirs[*]-} " != *" $d "* ]]; then
      libdirs+=("$d")
    fi
  done
  for f in "${pkgs[@]}" "${mods[@]}"; do
    echo "file $f"
  done
  for d in "${libdirs[@]+"${libdirs[@]}"}"; do
    echo "libdir $d"
  done
}

if [[ $# -ge 1 && "$1" == "--files" ]]; then
  [[ $# -eq 2 ]] || usage
  list_files "$2"
  exit 0
fi
[[ $# -ge 1 && "$1" != -* ]] || usage
module="$1"
shift

verilator="${VERILATOR:-verilator}"
if ! command -v "$verilator" > /dev/null 2>&1; then
  echo "rtl_lint: '${verilator}' not found; install Verilator 5.006 or set VERILATOR" >&2
  exit 1
fi

listing="$(list_files "$module")"
files=()
args=()
while read -r kind path; do
  case "$kind" in
    file) files+=("$path") ;;
    libdir) args+=(-y "$path") ;;
  esac
done <<< "$listing"

for p in "$@"; do
  if [[ ! "$p" =~ ^[A-Za-z_][A-Za-z0-9_]*=.+$ ]]; then
    echo "rtl_lint: expected Param=value, got '$p'" >&2
    exit 2
  fi
  args+=("-G$p")
done

work="$(mktemp -d "${TMPDIR:-/tmp}/scw_rtl_lint.XXXXXX")"
trap 'rm -rf "$work"' EXIT

# A package is a catalogue of shared constants: a module that uses one of them must not be
# told that the others are unused (Verilator -Wall reports every unused parameter of a
# package as soon as one is used in an expression). Only that rule, only for packages.
{
  echo '`verilator_config'
  while IFS= read -r f; do
    echo "lint_off -rule UNUSEDPARAM -file \"*/${f##*/}\""
  done < <(packages_among "${files[@]}")
} > "$work/package_waivers.vlt"

status=0
"$verilator" --lint-only -Wall +libext+.sv --top-module "$module" "${args[@]}" \
  "$work/package_waivers.vlt" "${files[@]}" > "$work/out.txt" 2>&1 || status=$?
cat "$work/out.txt"
if [[ $status -ne 0 ]] || grep -q '^%\(Warning\|Error\)' "$work/out.txt"; then
  echo "rtl_lint: ${module}: FAIL (verilator --lint-only -Wall reported the messages above)" >&2
  exit 1
fi
echo "rtl_lint: ${module}: clean (verilator --lint-only -Wall, ${#files[@]} files, 0 warnings)"
