#!/usr/bin/env bash
# Redraws the README's pictures of a real model with the tool itself: WusonOBJ.obj, a bull
# from Debian's assimp-testmodels (installed by `bash tools/install_deps.sh test`), seen from
# azimuth 120, elevation 20, in the four ways haloplot draws a model, and the README's quick
# start: the bull's STL on an A4 landscape page (its edge drawn in grey for the picture only).
# Writes docs/model-*.png and docs/quickstart-a4.png.
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
"$tool" plot "$model" --view $view --mode hidden-removed -o "$work/hidden-removed.svg"
"$tool" plot "$model" --view $view --mode hidden-dashed --dash 1,1 -o "$work/hidden-dashed.svg"
"$tool" plot "$model" --view $view --mode hidden-removed --hatch 1 -o "$work/hatched.svg"
stl=/usr/share/assimp/models/STL/Wuson.stl
"$tool" plot "$stl" --view $view --mode hidden-removed --page a4 --landscape -o "$work/a4.svg" \
  --gcode "$work/a4.gcode"
sed 's|viewBox="0 0 297 210">|&<rect x="0" y="0" width="297" height="210" fill="white" stroke="#999" stroke-width="0.6"/>|' \
  "$work/a4.svg" > "$work/a4-edge.svg"
rsvg-convert -w 600 "$work/a4-edge.svg" -o "$root/docs/quickstart-a4.png"
echo "wrote docs/quickstart-a4.png"
for p in haloed hidden-removed hidden-dashed hatched; do
  rsvg-convert -w 600 -b white "$work/$p.svg" -o "$root/docs/model-$p.png"
  echo "wrote docs/model-$p.png"
done
