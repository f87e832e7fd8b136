#!/usr/bin/env bash
# Maps per second: COUNT maps converted by one `shpack convert ... --out-dir` process against
# COUNT `shpack convert` processes one after the other, which is what start-up costs a
# pipeline that calls shpack once a map. The maps are the bundled data/hdri/*.exr, repeated
# (as links under new names) to COUNT files.
#
#   bench/batch_vs_processes.sh [BUILD_DIR] [COUNT]     defaults: build, 100
set -euo pipefail

repo=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-build}
count=${2:-100}
shpack=$build/cli/shpack
[[ -x $shpack ]] || { echo "batch_vs_processes: $shpack: not built (cmake --build $build)" >&2; exit 1; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir "$work/maps" "$work/one" "$work/many"
bundled=("$repo"/data/hdri/*.exr)
for ((i = 0; i < count; ++i)); do
  ln -s "${bundled[i % ${#bundled[@]}]}" "$work/maps/map$i.exr"
done

seconds() {  # wall seconds of the command, from bash's microsecond clock
  local start=$EPOCHREALTIME
  "$@"
  awk -v a="$start" -v b="$EPOCHREALTIME" 'BEGIN { printf "%.3f\n", b - a }'
}
one_process() { "$shpack" convert "$work"/maps/*.exr --out-dir "$work/one" >/dev/null; }
many_processes() {
  for map in "$work"/maps/*.exr; do "$shpack" convert "$map" -o "$work/many/$(basename "$map" .exr).json"; done
}

one_process  # warm the page cache and the loader
one=$(seconds one_process)
many=$(seconds many_processes)
echo "$count maps (data/hdri/*.exr repeated)"
awk -v s="$one" -v n="$count" 'BEGIN { printf "one process, --out-dir:  %.3f s, %.1f maps/s\n", s, n / s }'
awk -v s="$many" -v n="$count" 'BEGIN { printf "%d processes:           %.3f s, %.1f maps/s\n", n, s, n / s }'
awk -v a="$many" -v b="$one" 'BEGIN { printf "ratio processes / one process: %.2f\n", a / b }'
