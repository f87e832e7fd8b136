#!/usr/bin/env bash
# Regenerates the measured parts of docs/accuracy.md and the plot docs/img/accuracy.png and
# .svg with `shpack bench`, every method over its full sweep:
#   between "bench:begin" and "bench:end"                      the bundled maps, and the plot;
#   between "bench-synthetic:begin" and "bench-synthetic:end"  the synthetic maps;
#   between "view-error:begin" and "view-error:end"            `bench --view-error` of the
#                                                              bundled maps, and its plot;
#   between "bench-scenes:begin" and "bench-scenes:end"        `bench` of the scenes outdoor,
#                                                              room_bounce1 and room_bounce3 (under
#                                                              a minute on 2 cores), and its plot.
# The prose around the markers is kept.
#
#   scripts/accuracy-doc.sh [BUILD_DIR]      default: build (Release, as quickstart.sh makes it)
set -euo pipefail

repo=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${1:-$repo/build}" && pwd)
doc=$repo/docs/accuracy.md
shpack=$build/cli/shpack
[[ -x $shpack ]] || { echo "accuracy-doc: $shpack: not built (cmake --build $build)" >&2; exit 1; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$repo/docs/img"
# Relative paths, so the tables name data/hdri/x.exr whoever runs this.
# --max-draws 128: qmc drawn until its error's interval is within 10 % (the default stops at
# the first round, for speed).
(cd "$repo" && "$shpack" bench data/hdri/*.exr --max-draws 128 --plot docs/img/accuracy) >"$work/bundled.md"
(cd "$repo" && "$shpack" bench --view-error data/hdri/*.exr --plot docs/img/view-error) >"$work/view-error.md"
(cd "$repo" && "$shpack" bench bench/scenes/outdoor.json bench/scenes/room_bounce1.json bench/scenes/room_bounce3.json \
  --plot docs/img/bake-accuracy) >"$work/scenes.md"
"$shpack" bench synthetic:band-limited synthetic:gradient synthetic:sun synthetic:texel --max-draws 128 >"$work/synthetic.md"

# Replaces the lines between "<!-- NAME:begin" and "<!-- NAME:end" of $work/doc.md by FILE.
splice() {
  local name=$1 file=$2
  grep -q "<!-- $name:begin" "$work/doc.md" && grep -q "<!-- $name:end" "$work/doc.md" ||
    { echo "accuracy-doc: $doc: no $name:begin/$name:end markers" >&2; exit 1; }
  awk -v begin="<!-- $name:begin" -v end="<!-- $name:end" -v file="$file" '
    index($0, begin) == 1 { print; while ((getline line < file) > 0) print line; skipping = 1; next }
    index($0, end) == 1   { skipping = 0 }
    !skipping             { print }
  ' "$work/doc.md" >"$work/next.md"
  mv "$work/next.md" "$work/doc.md"
}
cp "$doc" "$work/doc.md"
splice bench "$work/bundled.md"
splice bench-synthetic "$work/synthetic.md"
splice view-error "$work/view-error.md"
splice bench-scenes "$work/scenes.md"
cp "$work/doc.md" "$doc"
echo "accuracy-doc: updated $doc and docs/img/{accuracy,view-error,bake-accuracy}.{png,svg}" >&2
