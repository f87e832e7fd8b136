#!/usr/bin/env bash
# The whole `shpack convert` process on a W x W/2 float EXR against a process that only
# decodes the same file with OpenEXR on the same number of threads and sums it
# (bench/decode_only.cpp). Targets (docs/accuracy.md): at most 1.5x at 1024x512, where
# start-up counts, and at most 1.05x at 4096x2048 and 16384x8192 (where convert streams in
# bands and the decoder holds the whole image). The map is data/hdri/courtyard.exr resized by
# oiiotool, stored as 32-bit float with ZIP compression (OpenEXR's usual lossless choice), so
# it has real content.
#
#   bench/convert_vs_decode.sh [BUILD_DIR] [RUNS] [W] [THREADS]   defaults: build, 21, 4096, 2
#
# Runs alternate between the two commands (which goes first flips each round, so a slow
# spell of the shared machine hits both), each timed as a wall-clock interval around the
# process; prints the medians and their ratio.
set -euo pipefail

repo=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-build}
runs=${2:-21}
width=${3:-4096}
threads=${4:-2}
height=$((width / 2))
shpack=$build/cli/shpack
decode=$build/bench/shpack_decode_only
for tool in "$shpack" "$decode"; do
  [[ -x $tool ]] || { echo "convert_vs_decode: $tool: not built (cmake --build $build)" >&2; exit 1; }
done
command -v oiiotool >/dev/null || { echo "convert_vs_decode: oiiotool: not installed (openimageio-tools)" >&2; exit 1; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
map=$work/map.exr
oiiotool "$repo/data/hdri/courtyard.exr" --resize ${width}x${height} -d float --compression zip -o "$map"

run_decode() { "$decode" "$map" "$threads" >/dev/null; }
run_convert() { "$shpack" convert "$map" --threads "$threads" -o "$work/out.json"; }
# Milliseconds taken by one command, from bash's microsecond clock.
time_ms() {
  local start=$EPOCHREALTIME
  "$@"
  local stop=$EPOCHREALTIME
  awk -v a="$start" -v b="$stop" 'BEGIN { printf "%.3f\n", (b - a) * 1000 }'
}

run_decode && run_convert  # warm the page cache and the loader
decode_ms=() convert_ms=()
for ((i = 0; i < runs; ++i)); do
  if ((i % 2 == 0)); then
    decode_ms+=("$(time_ms run_decode)"); convert_ms+=("$(time_ms run_convert)")
  else
    convert_ms+=("$(time_ms run_convert)"); decode_ms+=("$(time_ms run_decode)")
  fi
done

median() { printf '%s\n' "$@" | sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
d=$(median "${decode_ms[@]}")
c=$(median "${convert_ms[@]}")
echo "map: ${width}x${height} float RGB EXR (ZIP), $(du -h "$map" | cut -f1); $runs interleaved runs each"
echo "decode only (OpenEXR, $threads threads):  median $d ms"
echo "shpack convert --threads $threads:        median $c ms"
awk -v c="$c" -v d="$d" 'BEGIN { printf "ratio convert / decode: %.3f\n", c / d }'
