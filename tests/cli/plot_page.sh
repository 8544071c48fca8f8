#!/usr/bin/env bash
# CTest plot_page: the plot SVG is plotter input on a page. A hidden-dashed, outlined, hatched
# model on A4 landscape with 10 mm margins: the SVG is exactly 297 x 210 mm, every point lies
# inside the margins, no <rect>, one Inkscape layer per kind of line the .spans file holds;
# a haloed plot's subpaths are the pen-down runs of the G-code `sim` writes for the same job
# (order and points, y flipped), and its HPGL's; a hidden-line job's G-code draws the same
# segments. The files are read by tests/cli/svg_page_check.py, not by the tool's code.
# Usage: plot_page.sh HALOPLOT
set -u
tool="$1"
check="python3 $(cd "$(dirname "$0")" && pwd)/svg_page_check.py"
# shellcheck source=../support/expect.sh
. "$(cd "$(dirname "$0")" && pwd)/../support/expect.sh"

"$tool" demo-scene --cubes 3 -o cubes.obj
page="--page a4 --landscape --margin 10"
keys=$'page a4\nlandscape on\nmargin 10\n'

# A hidden-dashed, outlined, hatched solid: the page, the margins, the layers.
"$tool" plot cubes.obj --mode hidden-dashed --outline --hatch 3 $page -o solid.svg --spans solid.spans
expect "$check page solid.svg 297 210 10" "the A4 landscape page and its margins"
labels=()
for k in $($check kinds solid.spans); do
  case $k in visible) labels+=("1 visible") ;; hidden) labels+=("2 hidden") ;;
    hatch) labels+=("4 hatching") ;; outline) labels+=("5 outlines") ;; esac
done
expect '[ ${#labels[@]} -eq 4 ] && $check layers solid.svg "${labels[@]}"' "one layer per kind of line"
expect 'grep -q "xmlns:inkscape=\"http://www.inkscape.org/namespaces/inkscape\"" solid.svg' "the inkscape namespace"

# The same job in `sim`: its G-code draws the same pen-down segments, at the same points.
printf 'scene cubes.obj\ndrawing hidden-dashed\noutline on\nhatch 3\n%s' "$keys" > solid.job
"$tool" sim solid.job -o solid.trace --gcode solid.gcode
expect "$check segments solid.svg solid.gcode" "the hidden-line job's G-code draws the SVG's segments"

# Haloed: one layer, planned as the controller plans it: the SVG's strokes are the G-code's
# and the HPGL's pen-down runs, in order, point for point.
"$tool" plot cubes.obj --halo 40 $page -o halo.svg
printf 'scene cubes.obj\ndrawing haloed\nhalo 40\n%s' "$keys" > halo.job
"$tool" sim halo.job -o halo.trace --gcode halo.gcode --hpgl halo.hpgl
expect "$check page halo.svg 297 210 10" "the haloed plot's page"
expect "$check gcode halo.svg halo.gcode" "subpaths are the G-code's pen-down runs"
expect "$check hpgl halo.svg halo.hpgl" "subpaths are the HPGL's pen-down runs"

# Lines where faces cross get their own layer, only when there are some.
# shellcheck source=../support/model_files.sh
source "$(cd "$(dirname "$0")" && pwd)/../support/model_files.sh"  # box
{ box 0 2 0 2 0 -2 1; box 0.7 2.6 0.4 2.5 -0.6 -2.7 9; } > pierced.obj
"$tool" plot pierced.obj --view 30,25 --mode hidden-removed -o cross.svg 2> /dev/null
"$tool" plot pierced.obj --view 30,25 --mode hidden-removed --no-intersections -o nocross.svg 2> /dev/null
expect '$check layers cross.svg "1 visible" "3 intersections"' "an intersection layer where faces cross"
expect '$check layers nocross.svg "1 visible"' "no intersection layer without them"

# The default page is A4 landscape with 10 mm margins; --scale S draws S mm per model unit
# (three cubes of 100 units at a pitch of 125, seen from the front: 350 units wide).
"$tool" plot cubes.obj --mode hidden-removed -o default.svg
expect "$check page default.svg 297 210 10" "the default page"
"$tool" plot cubes.obj --mode hidden-removed --view 0,0 --scale 0.2 --page a5 --margin 5 -o scale.svg
expect '$check page scale.svg 148 210 5 && [ "$($check extent scale.svg)" = 70.000 ]' "--scale 0.2: 70 mm wide on A5 portrait"
"$tool" plot cubes.obj --mode hidden-removed --page 300x100 --landscape --margin 0 -o wide.svg
expect "$check page wide.svg 300 100 0" "a WxH page"

# Refused by name, nothing written.
"$tool" plot cubes.obj --mode hidden-removed --page b7 -o x.svg 2> err.txt
expect '[ ! -e x.svg ] && grep -q -- "--page .b7. must be" err.txt' "an unknown page is refused"
"$tool" plot cubes.obj --mode hidden-removed --scale 9 -o x.svg 2> err.txt
expect '[ ! -e x.svg ] && grep -q "larger than the page" err.txt' "a scale too large for the page is refused"
"$tool" demo-scene --cubes 2 -o two.edges
"$tool" plot two.edges --halo 5 --scale 1 -o x.svg 2> err.txt
expect '[ ! -e x.svg ] && grep -q -- "--scale is for models" err.txt' "--scale on an .edges scene is refused"
printf 'scene two.edges\nhalo 5\nscale 2\n' > two.job
"$tool" sim two.job -o x.trace 2> err.txt
expect '[ ! -e x.trace ] && grep -q "two.job:3: scale is for a model scene" err.txt' "a job's scale on an .edges scene is refused"
"$tool" plot two.edges --halo 5 --steps-per-mm 40 -o off.svg 2> err.txt
expect 'grep -q "warning: the drawing reaches beyond the 297 x 210 mm page" err.txt' "an .edges scene off the page is said"
"$tool" plot cubes.obj --mode hidden-removed --background -o bg.svg
expect '[ "$(grep -c "<rect" bg.svg)" = 1 ]' "--background adds the one rectangle"

echo "plot_page: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
