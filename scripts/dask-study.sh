#!/usr/bin/env bash
# Measures bakes on Dask distributed (python3 -m shpack.dask, docs/scale.md) against the
# one-machine bake, as whole processes paired run by run (farm-bench, median of 3 pairs), on
# bundled scenes, and prints the table of docs/scale.md ("Measured"):
#   2 workers / 1 worker        the speed-up of a second worker (4 shards each);
#   dask, 2 workers / bake      what Dask costs against `shpack bake --threads 2`;
#   per shard                   (T(16 shards) - T(1 shard)) / 15 on one worker: a shard's
#                               fixed cost (start the command, load the scene, build the
#                               ray tracer, rasterise the lightmaps, send the part back).
#
#   scripts/dask-study.sh [BUILD_DIR]      default: build (with -DSHPACK_BUILD_PYTHON=ON)
set -euo pipefail

repo=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${1:-$repo/build}" && pwd)
shpack=$build/cli/shpack
[[ -x $shpack && -f $build/python/shpack/dask.py ]] ||
  { echo "dask-study: build $build with -DSHPACK_BUILD_PYTHON=ON first" >&2; exit 1; }
command -v farm-bench >/dev/null || { echo "dask-study: farm-bench is not on PATH" >&2; exit 1; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export SHPACK_CLI=$shpack PYTHONPATH=$build/python
dask=(/usr/bin/python3 -m shpack.dask --quiet)

# The median of one figure ("A/B wall", "A wall s") of a farm-bench report on stdin.
median() { awk -v key="$1" 'index($0, key) == 1 { n = split($0, f, " "); print f[n - 1] }'; }
pair() {  # A, B: the median wall ratio A/B over 3 pairs
  farm-bench -n 3 --warmup 0 --timeout 3600 --vs "$2" -- $1 | median "A/B wall"
}

echo "| scene | one machine s | dask, 1 worker s | 2 workers / 1 worker | dask, 2 workers / bake | per shard s |"
echo "|---|---|---|---|---|---|"
for scene in room_bounce3 outdoor_lightmap box_lightmap; do
  file=$repo/bench/scenes/$scene.json
  one="$shpack bake $file -o $work/one.json --quiet --threads 2"
  w1="${dask[*]} $file -o $work/w1.json --workers 1 --shards 4"
  w2="${dask[*]} $file -o $work/w2.json --workers 2 --shards 4"
  s1="${dask[*]} $file -o $work/s1.json --workers 1 --shards 1"
  s16="${dask[*]} $file -o $work/s16.json --workers 1 --shards 16"
  t_one=$(farm-bench -n 3 --warmup 0 --timeout 3600 -- $one | median "A wall s")
  t_w1=$(farm-bench -n 3 --warmup 0 --timeout 3600 -- $w1 | median "A wall s")
  speedup=$(pair "$w2" "$w1")
  versus=$(pair "$w2" "$one")
  shards=$(farm-bench -n 3 --warmup 0 --timeout 3600 --vs "$s1" -- $s16 | awk '
    index($0, "A wall s") == 1 { n = split($0, f, " "); a = f[n - 1] }
    index($0, "B wall s") == 1 { n = split($0, f, " "); b = f[n - 1] }
    END { printf "%.2f", (a - b) / 15 }')
  echo "| $scene | $t_one | $t_w1 | $speedup | $versus | $shards |"
done
