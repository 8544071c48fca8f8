#!/usr/bin/env bash
# plot and sim of a scene with Bézier edges (docs/cli.md, "Scenes with curved edges"): the
# demo trefoil haloed, its SVG's strokes the G-code's pen-down runs point for point, one stroke
# per gap (a closed knot with 3 crossings and W small against the crossings' distance: 3 gaps,
# 3 strokes), sim of the same job the same G-code bytes; the options a curve scene cannot take
# refused by name with nothing written; a scene without curves still plots through CUT.
set -u
tool="$1"
src="$2"
# shellcheck source=../support/checks.sh
. "$(cd "$(dirname "$0")" && pwd)/../support/checks.sh"
check="python3 $src/tests/cli/svg_page_check.py"

cd "$work"
"$tool" demo-scene --curve trefoil -o trefoil.edges || bad "demo-scene --curve trefoil"
expect '[ "$(grep -c ^bezier trefoil.edges)" = 24 ]' "the demo trefoil has 24 bezier records"
"$tool" plot trefoil.edges --halo 80 -o t.svg --spans t.spans --gcode t.gcode --hpgl t.hpgl \
  --stats 2> t.txt || bad "plot trefoil.edges: $(cat t.txt)"
expect 'grep -q "^crossings=3$" t.txt && grep -q "^gaps=3$" t.txt' "3 crossings, 3 gaps"
expect '[ "$($check count t.svg)" = 3 ]' "3 strokes in the SVG (a closed knot with 3 gaps)"
expect '$check gcode t.svg t.gcode > /dev/null' "the SVG's strokes are the G-code's runs"
expect '$check hpgl t.svg t.hpgl > /dev/null' "the SVG's strokes are the HPGL's runs"
expect '[ "$(grep -c "^s " t.spans)" = "$(sed -n "s/^chords=//p" t.txt)" ]' "a spans line a chord"
# The same drawing as a job: sim plots the chords whole and writes the same G-code.
printf 'scene trefoil.edges\ndrawing haloed\nhalo 80\nhalo-mode paper\n' > t.job
"$tool" sim t.job -o t.trace --gcode s.gcode 2> sim.txt || bad "sim t.job: $(cat sim.txt)"
expect 'cmp -s t.gcode s.gcode' "sim of the job writes plot's G-code"
# A wider halo leaves less ink; halo 0 draws the knot whole: one closed stroke.
"$tool" plot trefoil.edges --halo 0 -o w.svg --stats 2> w.txt || bad "plot --halo 0"
expect '[ "$($check count w.svg)" = 1 ] && grep -q "^gaps=0$" w.txt' "halo 0: one stroke, no gap"
# Refused by name, nothing written.
# (An arena is taken, in bands: tests/cli/curve_bands.sh; not with the exact halo, drawn whole,
# nor with the plotter files of the whole drawing's path.)
for opt in "--cell 100" "--exact-halo --arena 65536" "--arena 65536 --gcode r.gcode" \
  "--cut x.cut" "--reach 4" "--view 10,20" "--substep 3"; do
  # shellcheck disable=SC2086
  if "$tool" plot trefoil.edges --halo 80 $opt -o r.svg 2> r.txt; then
    bad "plot of a curve scene with $opt succeeded"
  else
    expect 'grep -q -- "${opt%% *}" r.txt && [ ! -e r.svg ]' "$opt refused by name, no output"
  fi
done
# The exact halo on the host: the same 3 gaps, ends within 1/4 step here of the paper's
# (curve_gap_arcs checks both against their references).
"$tool" plot trefoil.edges --halo 80 --exact-halo -o e.svg --stats 2> e.txt || bad "--exact-halo"
expect 'grep -q "^gaps=3$" e.txt && [ "$($check count e.svg)" = 3 ]' "--exact-halo: 3 gaps, 3 strokes"
printf 'scene trefoil.edges\ndrawing haloed\nhalo 80\nhalo-mode exact\n' > e.job
expect '! "$tool" sim e.job -o e.trace 2> /dev/null && [ ! -e e.trace ]' "sim refuses the exact halo"
expect '! "$tool" cut trefoil.edges -o t.cut 2> c.txt && grep -q "straight edges only" c.txt' \
  "cut still refuses bezier records"
# A knot in perspective: its image fitted as cubics (more edges than the 24 steps), plotted as
# any curve scene; as a job too. The helix and an eye inside the knot refused.
"$tool" demo-scene --curve trefoil --perspective 300000 -o persp.edges || bad "--perspective"
expect '[ "$(grep -c ^bezier persp.edges)" -gt 24 ] && grep -q "in perspective from 300000" persp.edges' \
  "the perspective trefoil: more than 24 bezier records, the header says so"
"$tool" plot persp.edges --halo 80 -o p.svg --stats 2> p.txt || bad "plot persp.edges: $(cat p.txt)"
expect 'grep -q "^crossings=3$" p.txt && grep -q "^gaps=3$" p.txt && [ "$($check count p.svg)" = 3 ]' \
  "the perspective trefoil: 3 crossings, 3 gaps, 3 strokes"
# And with the exact halo: a perspective knot plotted with exact gaps, to G-code too.
"$tool" plot persp.edges --halo 80 --exact-halo -o pe.svg --gcode pe.gcode --stats 2> pe.txt ||
  bad "plot persp.edges --exact-halo: $(cat pe.txt)"
expect 'grep -q "^gaps=3$" pe.txt && [ "$($check count pe.svg)" = 3 ] && $check gcode pe.svg pe.gcode > /dev/null' \
  "the perspective trefoil with the exact halo: 3 gaps, 3 strokes, the G-code's runs"
printf 'scene persp.edges\ndrawing haloed\nhalo 80\nhalo-mode paper\n' > p.job
expect '"$tool" sim p.job -o p.trace 2> /dev/null' "sim of the perspective trefoil's job"
expect '! "$tool" demo-scene --curve helix --perspective 300000 -o x.edges 2> /dev/null && [ ! -e x.edges ]' \
  "--perspective refused for the helix"
expect '! "$tool" demo-scene --curve trefoil --perspective 1000 -o x.edges 2> /dev/null && [ ! -e x.edges ]' \
  "--perspective with the eye inside the knot refused"
# Other demo curves and bad names.
"$tool" demo-scene --curve helix -o helix.edges && "$tool" plot helix.edges --halo 40 -o h.svg \
  --stats 2> h.txt || bad "helix"
expect 'grep -q "^crossings=11$" h.txt && grep -q "^gaps=11$" h.txt' "helix: 11 crossings, 11 gaps"
expect '! "$tool" demo-scene --curve torus-2 -o x.edges 2> /dev/null && [ ! -e x.edges ]' \
  "--curve torus-2 refused"
# A straight scene still goes through CUT and DRAW.
"$tool" demo-scene --cubes 3 -o cubes.edges
"$tool" plot cubes.edges --halo 10 -o c.svg --stats 2> cs.txt || bad "plot cubes.edges"
expect 'grep -q "^cut_ms=" cs.txt && ! grep -q "^curve_pieces=" cs.txt' "straight scene: CUT ran"

echo "curve_plot: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
