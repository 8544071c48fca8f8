#!/usr/bin/env bash
# CTest plot_layers: a hidden-line drawing is plotted layer by layer, in the SVG's layer order
# (visible, hidden dashes, intersection lines, hatching, outlines). For two pierced boxes drawn
# hidden-dashed, hatched and outlined (all five layers): the G-code's pen-down runs are the
# SVG's subpaths in order, point for point, and the HPGL's; no M0 unless asked; with
# --pause-between-layers an M0, the pen up, exactly between layers, the parts between them the
# layers themselves, and the HPGL selecting each layer's pen by its number; a job's
# `pause-between-layers on` writes the same bytes through `sim`; the drawings of one layer and
# banded plots refuse it. The files are read by tests/cli/svg_page_check.py, not by the tool.
# Usage: plot_layers.sh HALOPLOT
set -u
tool="$1"
check="python3 $(cd "$(dirname "$0")" && pwd)/svg_page_check.py"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
pass=0 fail=0
expect() { if eval "$1" > out.txt 2>&1; then pass=$((pass + 1)); echo "ok: $(tail -1 out.txt)"; else fail=$((fail + 1)); echo "FAILED: $2: $(cat out.txt)"; fi; }

# shellcheck source=../support/model_files.sh
source "$(cd "$(dirname "$0")" && pwd)/../support/model_files.sh"  # box
{ box 0 2 0 2 0 -2 1; box 0.7 2.6 0.4 2.5 -0.6 -2.7 9; } > pierced.obj
drawing="--view 30,25 --mode hidden-dashed --outline --hatch 1"
all_five='"1 visible" "2 hidden" "3 intersections" "4 hatching" "5 outlines"'

# Without pauses: every layer, drawn in the SVG's order, and no M0.
# shellcheck disable=SC2086
"$tool" plot pierced.obj $drawing -o plain.svg --gcode plain.gcode --hpgl plain.hpgl 2> /dev/null
expect "$check layers plain.svg $all_five" "the drawing has all five layers"
expect "$check gcode plain.svg plain.gcode" "the G-code draws the SVG's subpaths in order"
expect "$check hpgl plain.svg plain.hpgl" "the HPGL draws the SVG's subpaths in order"
expect "$check pauses plain.svg plain.gcode plain.hpgl 0" "no pause unless asked"

# With pauses: the same strokes, an M0 between layers, a pen per layer in the HPGL.
# shellcheck disable=SC2086
"$tool" plot pierced.obj $drawing --pause-between-layers -o paused.svg --gcode paused.gcode \
  --hpgl paused.hpgl 2> /dev/null
expect "cmp -s plain.svg paused.svg" "the pause leaves the SVG alone"
expect "$check pauses paused.svg paused.gcode paused.hpgl 5" "M0 and SPn exactly between the layers"
expect "$check gcode paused.svg paused.gcode" "the paused G-code draws the SVG's subpaths in order"

# A job with the key: `sim` writes the same files (and without it, the unpaused ones).
printf 'scene pierced.obj\nview 30,25\ndrawing hidden-dashed\noutline on\nhatch 1\n' > plain.job
cp plain.job paused.job
printf 'pause-between-layers on\n' >> paused.job
for name in plain paused; do
  "$tool" sim $name.job -o $name.trace --gcode $name.s.gcode --hpgl $name.s.hpgl 2> /dev/null
  expect "cmp -s $name.gcode $name.s.gcode && cmp -s $name.hpgl $name.s.hpgl" \
    "sim of the $name job writes plot's G-code and HPGL"
done

# Two layers (visible and outlines) with a Z pen: one M0, the pen lifted before it.
"$tool" demo-scene --cubes 2 -o cubes.obj
"$tool" plot cubes.obj --mode hidden-removed --no-intersections --outline -o two.svg \
  --gcode two.gcode --hpgl two.hpgl --pen z --pause-between-layers 2> /dev/null
expect "$check pauses two.svg two.gcode two.hpgl 2" "a Z pen's pause between two layers"

# Refused by name: one layer to plot, no plotter output, a plot in bands.
refused() {  # "COMMAND" "PATTERN" "WHAT"
  eval "$1" 2> err.txt
  local rc=$?
  expect "[ $rc -ne 0 ] && grep -q -- \"$2\" err.txt && [ ! -e x.gcode ] && [ ! -e x.trace ]" \
    "$3: $(cat err.txt)"
}
refused "'$tool' plot cubes.obj --mode all -o x.svg --gcode x.gcode --pause-between-layers" \
  "--pause-between-layers with --mode all" "mode all draws one layer"
refused "'$tool' plot cubes.obj --halo 40 -o x.svg --gcode x.gcode --pause-between-layers" \
  "--pause-between-layers with --mode haloed" "a haloed drawing is one layer"
refused "'$tool' plot cubes.obj --mode hidden-removed -o x.svg --pause-between-layers" \
  "add --gcode" "a pause without G-code or HPGL"
printf 'scene cubes.obj\ndrawing haloed\nhalo 40\npause-between-layers on\n' > halo.job
refused "'$tool' sim halo.job -o x.trace --gcode x.gcode" \
  "halo.job:4: pause-between-layers needs drawing hidden-removed" "a job's pause with one layer"
refused "'$tool' sim paused.job -o x.trace --gcode x.gcode --arena 65536" \
  "pause-between-layers with an arena" "a pause in a banded plot"

echo "plot_layers: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
