#!/usr/bin/env bash
# The whole `shpack convert` process against Filament's cmgen computing L2 SH of the same map
# (`cmgen --sh=3`, Debian's libfilament-tools), one map at a time, on the bundled maps. cmgen
# cannot read DWAB, so each map is first re-stored losslessly with ZIP compression by
# oiiotool (the pixels are the same), and both tools read that copy.
#
#   bench/cmgen_vs_convert.sh [BUILD_DIR] [RUNS]     defaults: build, 11
#
# Runs alternate between the two commands; prints each map's medians and their ratio.
set -euo pipefail

repo=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-build}
runs=${2:-11}
shpack=$build/cli/shpack
[[ -x $shpack ]] || { echo "cmgen_vs_convert: $shpack: not built (cmake --build $build)" >&2; exit 1; }
for tool in cmgen oiiotool; do
  command -v $tool >/dev/null || { echo "cmgen_vs_convert: $tool: not installed" >&2; exit 1; }
done

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
time_ms() {
  local start=$EPOCHREALTIME
  "$@"
  awk -v a="$start" -v b="$EPOCHREALTIME" 'BEGIN { printf "%.3f\n", (b - a) * 1000 }'
}
median() { printf '%s\n' "$@" | sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

echo "| map | cmgen --sh=3 | shpack convert | shpack / cmgen |"
echo "|---|---:|---:|---:|"
for original in "$repo"/data/hdri/*.exr; do
  map=$work/$(basename "$original")
  oiiotool "$original" --compression zip -o "$map"
  run_cmgen() { (cd "$work" && cmgen -q --sh=3 --sh-output="$work/sh.txt" "$map" >/dev/null); }
  run_convert() { "$shpack" convert "$map" -o "$work/out.json"; }
  run_cmgen && run_convert  # warm the page cache and the loader
  cmgen_ms=() convert_ms=()
  for ((i = 0; i < runs; ++i)); do
    cmgen_ms+=("$(time_ms run_cmgen)")
    convert_ms+=("$(time_ms run_convert)")
  done
  g=$(median "${cmgen_ms[@]}")
  c=$(median "${convert_ms[@]}")
  awk -v n="$(basename "$map")" -v g="$g" -v c="$c" 'BEGIN { printf "| %s | %.1f ms | %.1f ms | %.3f |\n", n, g, c, c / g }'
done
