#!/usr/bin/env bash
# A curve job in bands (docs/bands.md, "Curves in bands"): the demo trefoil haloed, as a job
# with an `arena` below what the whole drawing takes in one band, plots in bands in `sim`, and
# its pen-down segments are the unbanded plot's within a step, read from the two G-code files
# by this test's own reader (gcode_pen_down.py); the reader tells the plot of a halo one step
# wider apart (the comparison can fail). `plot --arena` writes the unbanded plot's spans and
# SVG byte for byte. The perspective trefoil the same. An arena too small for a band one row
# high is refused with what the band asked for, and no trace.
set -u
tool="$1"
src="$2"
# shellcheck source=../support/checks.sh
. "$(cd "$(dirname "$0")" && pwd)/../support/checks.sh"
compare="python3 $src/tests/cli/gcode_pen_down.py"

cd "$work"
"$tool" demo-scene --curve trefoil -o trefoil.edges || bad "demo-scene --curve trefoil"
job() {  # job NAME SCENE HALO [ARENA]
  printf 'scene %s\ndrawing haloed\nhalo %s\nhalo-mode paper\nkinematics corexy\nsteps 1/4\n' \
    "$2" "$3" > "$1"
  if [ -n "${4:-}" ]; then echo "arena $4" >> "$1"; fi
}
stat_of() { sed -n "s/^$1=//p" "$2"; }
arena=24576
job whole.job trefoil.edges 80
job one.job trefoil.edges 80 16777216
job band.job trefoil.edges 80 $arena
job wider.job trefoil.edges 81
"$tool" sim whole.job -o whole.trace --gcode whole.gcode 2> whole.txt || bad "sim whole.job: $(cat whole.txt)"
"$tool" sim one.job -o one.trace --stats 2> one.txt || bad "sim one.job: $(cat one.txt)"
need=$(stat_of band_peak_bytes one.txt)
expect '[ "$(stat_of bands one.txt)" = 1 ] && [ "${need:-0}" -gt $arena ]' \
  "the whole drawing in one band needs more than $arena bytes (${need:-?})"
"$tool" sim band.job -o band.trace --gcode band.gcode --stats 2> band.txt || bad "sim band.job: $(cat band.txt)"
bands=$(stat_of bands band.txt)
expect '[ "${bands:-0}" -ge 2 ] && [ "$(stat_of band_peak_bytes band.txt)" -le $arena ]' \
  "in $arena bytes: ${bands:-?} bands, peak $(stat_of band_peak_bytes band.txt) bytes"
out=$($compare whole.gcode band.gcode)
rc=$?
echo "banded against unbanded: $out"
expect '[ $rc -eq 0 ]' "the banded plot's pen-down segments are the unbanded plot's within a step"
"$tool" sim wider.job -o wider.trace --gcode wider.gcode 2> wider.txt || bad "sim wider.job"
out=$($compare wider.gcode band.gcode)
rc=$?
echo "against the plot of halo 81 (must differ): $out"
expect '[ $rc -eq 1 ]' "the reader tells the halo-81 plot from the banded halo-80 one"
expect '! cmp -s whole.trace band.trace' "the banded plot's trace is its own (the pen lifts at borders)"

# plot --arena: the same drawing's files, byte for byte.
"$tool" plot trefoil.edges --halo 80 -o p.svg --spans p.spans 2> p.txt || bad "plot: $(cat p.txt)"
"$tool" plot trefoil.edges --halo 80 --arena $arena -o pb.svg --spans pb.spans --stats 2> pb.txt ||
  bad "plot --arena: $(cat pb.txt)"
expect 'cmp -s p.spans pb.spans && cmp -s p.svg pb.svg' "plot --arena writes plot's spans and SVG"
expect '[ "$(stat_of bands pb.txt)" = "$bands" ]' "plot --arena takes sim's bands"
"$tool" plot trefoil.edges --halo 81 -o w.svg --spans w.spans 2> /dev/null
expect '! cmp -s w.spans pb.spans' "the spans of halo 81 differ (the comparison can fail)"

# The perspective trefoil (75 edges) in bands.
"$tool" demo-scene --curve trefoil --perspective 300000 -o persp.edges || bad "--perspective"
job pwhole.job persp.edges 80
job pband.job persp.edges 80 $arena
"$tool" sim pwhole.job -o pw.trace --gcode pw.gcode 2> pw.txt || bad "sim pwhole.job: $(cat pw.txt)"
"$tool" sim pband.job -o pb.trace --gcode pb.gcode --stats 2> pbs.txt || bad "sim pband.job: $(cat pbs.txt)"
out=$($compare pw.gcode pb.gcode)
rc=$?
echo "perspective trefoil, $(stat_of bands pbs.txt) bands: $out"
expect '[ $rc -eq 0 ] && [ "$(stat_of bands pbs.txt)" -ge 2 ]' "the perspective trefoil in bands"

# Too small: refused with the bytes a band asked for, no trace left.
job tiny.job trefoil.edges 80 8192
expect '! "$tool" sim tiny.job -o tiny.trace 2> tiny.txt && grep -q "too small: a band one row high needs" tiny.txt && [ ! -e tiny.trace ]' \
  "an arena too small for a band: refused, with its need"

echo "curve_bands_cli: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
