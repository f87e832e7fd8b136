#!/usr/bin/env bash
# Regenerates docs/gallery.md and its images docs/img/<map>.png from the bundled maps in
# data/hdri: for each map, `shpack convert` with the default options, then `shpack preview
# --input` (lit spheres, E/pi, the exact reference and the error map). Builds the
# shpack command first (Release, into $SHPACK_BUILD_DIR, default build/, as quickstart.sh).
set -euo pipefail
cd "$(dirname "$0")/.."

build=${SHPACK_BUILD_DIR:-build}
if [[ ! -f $build/CMakeCache.txt ]]; then  # an existing build keeps its own options
  cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DSHPACK_BUILD_TESTS=OFF -DSHPACK_BUILD_BENCH=OFF >/dev/null
fi
cmake --build "$build" -j"$(nproc)" --target shpack >/dev/null
shpack=$build/cli/shpack

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p docs/img

# What follows the label on the line of the preview's report that starts with it.
field() {
  local line
  line=$(grep -F "$1" "$2")
  echo "${line#"$1"}"
}

{
  cat <<'HEADER'
# Gallery

The bundled maps (`data/hdri`, see its README) as `shpack preview` shows them. Regenerate
this page and its images with `scripts/gallery.sh` (it builds `shpack` first).

Each image: a white diffuse sphere lit by the map's SH as Unity's `ShadeSH9` lights it, seen
from -Z (front) and from +Y (top); E/pi over all directions as an equirect map (centre +X);
below, the exact E/pi of the map itself (within a stated bound) (the reference) and the luminance of the
difference, blue where the SH is too dark and red where it is too bright, on a colour bar
labelled with its ends. Magenta stripes mark directions where the SH gives negative E/pi (the
built-in Standard shader clamps them to 0). All panels share one tone mapping: Reinhard
x/(1+x) per channel after scaling the mean E/pi to 0.5, then sRGB. `lib/io/include/shpack/io/preview.h`
gives the details and the derivation of the reference's error bound.

Made with `shpack convert MAP -o MAP.json` (default options: exact projection, no window)
and `shpack preview MAP.json -o docs/img/MAP.png --input MAP`.

| map | E/pi < 0 on | reference error bound | SH - reference: max, rms (luminance, share of the mean) |
|---|---|---|---|
HEADER
  for map in data/hdri/*.exr; do
    name=$(basename "$map" .exr)
    "$shpack" convert "$map" -o "$work/$name.json"
    "$shpack" preview "$work/$name.json" -o "docs/img/$name.png" --input "$map" >"$work/$name.txt"
    negative=$(field "negative E/pi (striped): " "$work/$name.txt")
    bound=$(field "reference: exact E/pi of the map's texels, error <= " "$work/$name.txt")
    error=$(field "sh - reference (luminance): max |error| " "$work/$name.txt")
    echo "| [$name](#$name) | ${negative% of the sphere} | $bound | $error |"
  done
  for map in data/hdri/*.exr; do
    name=$(basename "$map" .exr)
    printf '\n## %s\n\n![%s: lit spheres, E/pi, reference and error](img/%s.png)\n' "$name" "$name" "$name"
  done
} >"$work/gallery.md"
mv "$work/gallery.md" docs/gallery.md
echo "gallery: wrote docs/gallery.md and docs/img/*.png" >&2
