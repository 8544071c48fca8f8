#!/usr/bin/env bash
# Redraws the README's pictures of a real model with the tool itself: WusonOBJ.obj, a bull
# from Debian's assimp-testmodels (installed by `bash tools/install_deps.sh test`), seen from
# azimuth 120, elevation 20, in the four ways haloplot draws a model, and the README's quick
# start: the bull's STL on an A4 landscape page (its edge drawn in grey for the picture only),
# and two knots as Bézier edges, haloed (each picture cropped to its drawing).
# Writes docs/model-*.png, docs/quickstart-a4.png and docs/knot-*.png.
# Usage: tools/make_doc_pictures.sh [HALOPLOT]   (default build/host/host_sim/haloplot)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
tool="${1:-$root/build/host/host_sim/haloplot}"
model=/usr/share/assimp/models/OBJ/WusonOBJ.obj
[ -f "$model" ] || { echo "no $model: apt-get install assimp-testmodels" >&2; exit 1; }
command -v rsvg-convert >/dev/null || { echo "no rsvg-convert: apt-get install librsvg2-bin" >&2; exit 1; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
view=120,20
"$tool" plot "$model" --view $view --halo 60 -o "$work/haloed.svg"
# The hidden-line modes as an illustrator draws a smooth model: contours and creases sharper
# than 40 degrees (Blender's Line Art's default crease), not the facets.
"$tool" plot "$model" --view $view --mode hidden-removed --crease 40 -o "$work/hidden-removed.svg"
"$tool" plot "$model" --view $view --mode hidden-dashed --crease 40 --dash 1,1 -o "$work/hidden-dashed.svg"
"$tool" plot "$model" --view $view --mode hidden-removed --crease 40 --hatch 1 -o "$work/hatched.svg"
stl=/usr/share/assimp/models/STL/Wuson.stl
# assimp's Wuson.stl was written from its Y-up OBJ: --up y (an STL is read Z-up by default).
"$tool" plot "$stl" --view $view --up y --mode hidden-removed --crease 40 --page a4 --landscape -o "$work/a4.svg" \
  --gcode "$work/a4.gcode"
sed 's|viewBox="0 0 297 210">|&<rect x="0" y="0" width="297" height="210" fill="white" stroke="#999" stroke-width="0.6"/>|' \
  "$work/a4.svg" > "$work/a4-edge.svg"
rsvg-convert -w 600 "$work/a4-edge.svg" -o "$root/docs/quickstart-a4.png"
echo "wrote docs/quickstart-a4.png"
for p in haloed hidden-removed hidden-dashed hatched; do
  rsvg-convert -w 600 -b white "$work/$p.svg" -o "$root/docs/model-$p.png"
  echo "wrote docs/model-$p.png"
done
# The knots: the demo trefoil and (2,5) torus knot (`demo-scene --curve`), haloed with a wide
# halo so the gaps show at this size; the SVG's page cropped to the drawing for the picture.
crop() {
  python3 - "$1" "$2" <<'PY'
import re, sys
s = open(sys.argv[1]).read()
pts = [tuple(map(float, m)) for m in re.findall(r"(-?\d+\.\d+),(-?\d+\.\d+)", s)]
x0, y0 = min(p[0] for p in pts) - 4, min(p[1] for p in pts) - 4
w, h = max(p[0] for p in pts) + 4 - x0, max(p[1] for p in pts) + 4 - y0
box = 'width="%.1fmm" height="%.1fmm" viewBox="%.2f %.2f %.2f %.2f"' % (w, h, x0, y0, w, h)
open(sys.argv[2], "w").write(re.sub(r'width="[^"]*" height="[^"]*" viewBox="[^"]*"', box, s, count=1))
PY
}
for knot in trefoil torus-2-5; do
  "$tool" demo-scene --curve "$knot" -o "$work/$knot.edges"
  "$tool" plot "$work/$knot.edges" --halo 600 -o "$work/$knot.svg"
  crop "$work/$knot.svg" "$work/$knot-cropped.svg"
  rsvg-convert -w 300 -b white "$work/$knot-cropped.svg" -o "$root/docs/knot-$knot.png"
  echo "wrote docs/knot-$knot.png"
done
