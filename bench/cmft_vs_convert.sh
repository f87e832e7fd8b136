#!/usr/bin/env bash
# The whole `shpack convert` process against cmft (github.com/dariomanesku/cmft) computing the
# spherical harmonics of the same map, one map at a time, on the bundled maps. cmft is built
# from source for this benchmark only; it is no dependency of shpack's build or tests.
#
#   bench/cmft_vs_convert.sh CMFT [BUILD_DIR] [RUNS]     defaults: -, build, 11
#
# cmft's SH-only run is the least work it does: `--filter shcoeffs --outputNum 1 --output0 F
# --silent` loads the map, turns the lat-long image into a cube map (faces of (height + 1) / 2, no
# --srcFaceSize resize, no mip chain: the shcoeffs filter returns before any of that) and
# writes 25 coefficients (bands 0-4; it has no L2-only mode) to F.c. cmft reads only DDS, KTX,
# Radiance .hdr and TGA (its --help lists *.exr, but its loader has no EXR reader), so each map
# is first converted by oiiotool to .hdr, and both tools read that copy (`hdr / hdr`; shpack
# reads .hdr with its own Radiance reader, lib/io/src/hdr_decoder.h, which loads no OpenImageIO).
# The `exr / hdr` column gives shpack the same pixels re-stored as 32-bit float ZIP EXR (read
# with OpenEXR) against cmft on the .hdr.
#
# Runs alternate between the commands (cmft, shpack on .hdr, shpack on EXR); each ratio is taken
# run by run and the median of those ratios printed, for wall time and for CPU time (user +
# system, bash's `time`).
#
# Building cmft (commit cad5f31b, 2019-08-05; GENie and bx are in its tree, no submodules;
# ~30 s on one core with gcc 12):
#
#   git clone https://github.com/dariomanesku/cmft /tmp/cmft-src   # or `git archive` of a copy
#   cd /tmp/cmft-src && make linux-release64 -j2                 # GENie gmake, linux-gcc
#   # binary: /tmp/cmft-src/_build/linux64_gcc/bin/cmftRelease
#   # (a copy without runtime/okretnica.tga, a sample map, builds the same: the build never reads it)
set -euo pipefail

repo=$(cd "$(dirname "$0")/.." && pwd)
cmft=${1:?usage: cmft_vs_convert.sh CMFT [BUILD_DIR] [RUNS]}
build=${2:-build}
runs=${3:-11}
shpack=$build/cli/shpack
[[ -x $shpack ]] || { echo "cmft_vs_convert: $shpack: not built (cmake --build $build)" >&2; exit 1; }
[[ -x $cmft ]] || { echo "cmft_vs_convert: $cmft: not an executable (see this script's header)" >&2; exit 1; }
command -v oiiotool >/dev/null || { echo "cmft_vs_convert: oiiotool: not installed" >&2; exit 1; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# "wall_ms cpu_ms" of one run of the command
time_ms() {
  local TIMEFORMAT='%3R %3U %3S' t
  t=$( { time "$@" >/dev/null 2>&1; } 2>&1 )
  awk -v t="$t" 'BEGIN { split(t, v, " "); printf "%.3f %.3f\n", v[1] * 1000, (v[2] + v[3]) * 1000 }'
}
median() { printf '%s\n' "$@" | sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

echo "| map | cmft shcoeffs (wall; CPU) | shpack convert .hdr | shpack convert .exr | hdr / hdr (wall; CPU) | exr / hdr (wall; CPU) |"
echo "|---|---:|---:|---:|---:|---:|"
for original in "$repo"/data/hdri/*.exr; do
  name=$(basename "$original" .exr)
  hdr=$work/$name.hdr exr=$work/$name.exr
  oiiotool "$original" -o "$hdr"
  oiiotool "$hdr" -d float --compression zip -o "$exr"
  run_cmft() { "$cmft" --input "$hdr" --filter shcoeffs --outputNum 1 --output0 "$work/sh" --silent; }
  run_hdr() { "$shpack" convert "$hdr" -o "$work/hdr.json"; }
  run_exr() { "$shpack" convert "$exr" -o "$work/exr.json"; }
  run_cmft && run_hdr && run_exr  # warm the page cache and the loader; fail on an error
  [[ -s $work/sh.c ]] || { echo "cmft_vs_convert: cmft wrote no $work/sh.c" >&2; exit 1; }
  cw=() cc=() hw=() hc=() ew=() ec=() rhw=() rhc=() rew=() rec=()
  for ((i = 0; i < runs; ++i)); do
    read -r a b < <(time_ms run_cmft); cw+=("$a") cc+=("$b")
    read -r c d < <(time_ms run_hdr); hw+=("$c") hc+=("$d")
    read -r e f < <(time_ms run_exr); ew+=("$e") ec+=("$f")
    rhw+=("$(awk -v x="$c" -v y="$a" 'BEGIN { print x / y }')")
    rew+=("$(awk -v x="$e" -v y="$a" 'BEGIN { print x / y }')")
    rhc+=("$(awk -v x="$d" -v y="$b" 'BEGIN { print (y > 0) ? x / y : "inf" }')")
    rec+=("$(awk -v x="$f" -v y="$b" 'BEGIN { print (y > 0) ? x / y : "inf" }')")
  done
  printf '| %s | %.1f; %.1f ms | %.1f; %.1f ms | %.1f; %.1f ms | %.3f; %.3f | %.3f; %.3f |\n' "$name" \
    "$(median "${cw[@]}")" "$(median "${cc[@]}")" "$(median "${hw[@]}")" "$(median "${hc[@]}")" \
    "$(median "${ew[@]}")" "$(median "${ec[@]}")" \
    "$(median "${rhw[@]}")" "$(median "${rhc[@]}")" "$(median "${rew[@]}")" "$(median "${rec[@]}")"
done
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg)"
