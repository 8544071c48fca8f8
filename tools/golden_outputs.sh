#!/usr/bin/env bash
# Every kind of output the tool writes, for a comparison before and after a change that must
# not change what a user sees (a refactoring): a haloed scene (the demo's cubes, fewer of
# them), a solid hidden-dashed with outlines and hatching, the same solid in bands through
# `sim`, and a curve plot, each to SVG, spans, G-code, HPGL and step trace.
#
#   tools/golden_outputs.sh HALOPLOT OUTDIR      writes the files and OUTDIR/SHA256SUMS
#   diff OLD/SHA256SUMS NEW/SHA256SUMS           empty when every byte is the same
set -eu
tool="$1" out="$2"
mkdir -p "$out"
cd "$out"
rm -f ./*.svg ./*.spans ./*.gcode ./*.hpgl ./*.trace ./*.job SHA256SUMS
"$tool" demo-scene --cubes 8 -o cubes8.edges
"$tool" demo-scene --cubes 3 -o cubes3.obj
"$tool" demo-scene --curve trefoil -o trefoil.edges
# Haloed: plot's files, then sim's trace of the same job.
"$tool" plot cubes8.edges --halo 60 -o haloed.svg --spans haloed.spans --gcode haloed.gcode \
  --hpgl haloed.hpgl 2> /dev/null
printf 'scene cubes8.edges\nhalo 60\n' > haloed.job
"$tool" sim haloed.job -o haloed.trace 2> /dev/null
# A solid, hidden-dashed, outlined and hatched.
solid=(--mode hidden-dashed --outline --hatch 2 --view 30,25)
"$tool" plot cubes3.obj "${solid[@]}" -o solid.svg --spans solid.spans --gcode solid.gcode \
  --hpgl solid.hpgl --pause-between-layers 2> /dev/null
printf 'scene cubes3.obj\ndrawing hidden-dashed\noutline on\nhatch 2\nview 30,25\n' > solid.job
"$tool" sim solid.job -o solid.trace 2> /dev/null
# The same solid in bands, as a controller with a 48 KB arena plots it.
{ cat solid.job; echo "arena 49152"; } > banded.job
"$tool" sim banded.job -o banded.trace --gcode banded.gcode --hpgl banded.hpgl 2> /dev/null
# Curves.
"$tool" plot trefoil.edges --halo 600 -o curve.svg --spans curve.spans --gcode curve.gcode \
  --hpgl curve.hpgl 2> /dev/null
printf 'scene trefoil.edges\nhalo 600\n' > curve.job
"$tool" sim curve.job -o curve.trace 2> /dev/null
sha256sum ./*.svg ./*.spans ./*.gcode ./*.hpgl ./*.trace > SHA256SUMS
wc -l < SHA256SUMS
