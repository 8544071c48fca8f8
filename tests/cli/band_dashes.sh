#!/usr/bin/env bash
# A hidden-line plot in bands draws the whole-model plot, dash for dash. For each
# solid (the 6 x 6 cubes of Figure 4, a torus, a sphere through a torus), hidden-dashed with
# outlines and hatching (the cubes also without hatching, as reported), and for smooth solids
# drawn with a crease angle (their silhouettes are contour diagonals: triangle sides that are
# no drawn edge), hidden-removed and hidden-dashed with outlines, `haloplot sim` plots the
# job whole and with arenas small enough for several bands; band_dashes_check
# (tests/tools/band_dashes_check.cpp, which reads the traces alone) compares the pen-down
# strokes, joined across the borders, with the whole-model trace's: every stroke end, every
# dash's included, within one step, in bands across the page turned a quarter (a drawing
# wider than tall) and in the page's rows (one taller than wide).
#   band_dashes.sh HALOPLOT BAND_DASHES_CHECK
set -u
here=$(cd "$(dirname "$0")" && pwd)
tool="$1"
check="$2"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
pass=0 fail=0 turned_runs=0 row_runs=0
ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAILED: $*" >&2; }
cd "$work"

"$tool" demo-scene --cubes 6 -o cubes6.obj || bad "demo-scene --cubes 6"
# A torus of 12 x 6 facets; the sphere through a torus of the firmware tests (10 x 5 and 6 x 5).
source "$here/../support/model_files.sh"
torus_obj 1.5 0.6 12 6 > torus.obj
torus_sphere_obj > torus_sphere.obj
# A torus of 24 x 12 facets: 15 and 30 degrees apart, every side smooth at a crease angle of 40.
torus_obj 1.5 0.6 24 12 > smooth_torus.obj
# One of 200 x 100 facets: its contour diagonals are shorter than a dash and a gap, dashed by
# where they lie on the page (solid/modes.h, page_dashes), in the turned frame too (read in the
# band's own frame instead, 41 strokes of the turned plot differ).
torus_obj 1.5 0.6 200 100 > dense_torus.obj

# NAME SCENE EXTRA-KEYS ARENA...: the whole-model trace, then one banded trace per arena;
# hidden-dashed, or DRAWING=MODE.
run() {
  local name="$1" scene="$2" extra="$3"
  shift 3
  # Clean-up off: a band's planner merges collinear overlaps of every kind in its column (one
  # pen), the whole plot's only within a layer; here the banding itself is compared.
  printf 'scene %s\ndrawing %s\nview 30,25\noutline on\ncleanup off\n%beffects acceleration pen-servo\nkinematics corexy\n' \
    "$scene" "${DRAWING:-hidden-dashed}" "$extra" > "$name.job"
  if ! "$tool" sim "$name.job" -o "$name.trace"; then
    bad "$name: the whole-model plot failed"
    return
  fi
  for arena in "$@"; do
    { cat "$name.job"; echo "arena $arena"; } > "${name}_$arena.job"
    if ! "$tool" sim "${name}_$arena.job" -o "${name}_$arena.trace" --stats 2> "${name}_$arena.stats"; then
      bad "$name in $arena bytes: the banded plot failed"
      continue
    fi
    bands=$(sed -n 's/^bands=//p' "${name}_$arena.stats")
    if [ "${bands:-0}" -lt 2 ]; then
      bad "$name in $arena bytes: $bands band(s), not a banded plot"
      continue
    fi
    turned=$(sed -n 's/^band_turned=//p' "${name}_$arena.stats")
    if [ "${turned:-}" = 1 ]; then frame="columns"; turned_runs=$((turned_runs + 1)); else
      frame="rows"; row_runs=$((row_runs + 1)); fi
    out=$("$check" "$name.trace" "${name}_$arena.trace")
    rc=$?
    echo "$name, arena $arena ($bands bands, $frame): $out"
    if [ "$rc" -eq 0 ]; then ok; else bad "$name in $arena bytes ($bands bands) draws another picture"; fi
  done
}

run cubes6 cubes6.obj '' 32768
run cubes6_hatched cubes6.obj 'hatch 3 30 90\n' 32768 49152 65536
# The hatched cubes at an eighth of a motor step (the pen placed to 8 plot steps, as on the
# controller) in arenas from 28 to 64 KB, 4 KB apart: every placement of the borders these give
# (3 to 17 bands) draws the whole-model plot. Here edges run within a step of nearly parallel
# dashed edges, where a stroke end of one plot can pair with either; the check pairs pieces
# one to one as a largest matching, not nearest first.
run cubes6_eighth cubes6.obj 'dash 2 1\nhatch 3 30 90\nsteps 1/8\n' $(seq 28672 4096 65536)
run torus torus.obj 'hatch 3 30 90\n' 16384 32768 65536
run torus_sphere torus_sphere.obj 'hatch 3 30 90\n' 16384 32768 65536
# The drawings above are wider than tall, so the conductor bands them in the page turned a
# quarter (bands are columns of the page: BandSpec::turn_wide). Rolled a quarter, the same
# pictures are taller than wide and banded in the page's rows: both frames draw the picture.
run cubes6_rolled cubes6.obj 'roll 90\ndash 2 1\nhatch 3 30 90\nsteps 1/8\n' 32768 49152
run torus_sphere_rolled torus_sphere.obj 'roll 90\nhatch 3 30 90\n' 16384 32768
# Smooth solids at a crease angle (`crease 40`): the sides left out as smooth are drawn only
# where they are contours, and a band finds them among its own triangles (no drawn edge to carry
# across a border), so their visible parts and the outlines along them are cut at the borders
# and joined there. The smooth torus has no drawn edge at all: its whole drawing is contour
# diagonals, in both frames. The sphere through the torus has creases too, and lines where the
# two cross. Not rolled: from this view one of its faces is seen nearly edge-on, and rolled a
# quarter its corners round onto one row, so a band, which has only the projected areas to tell
# a face's facing, takes it for a back face and its diagonal for a contour, where the
# whole-model plot has the model's facing (view/facing.h): front, no contour.
for drawing in hidden-removed hidden-dashed; do
  DRAWING=$drawing run "smooth_torus_$drawing" smooth_torus.obj 'crease 40\n' 8192 16384 24576
  DRAWING=$drawing run "smooth_torus_rolled_$drawing" smooth_torus.obj 'roll 90\ncrease 40\n' 8192 16384
done
run dense_torus dense_torus.obj 'crease 40\n' 65536 131072
run dense_torus_rolled dense_torus.obj 'roll 90\ncrease 40\n' 65536 131072
DRAWING=hidden-removed run torus_sphere_crease torus_sphere.obj 'crease 40\n' 8192 12288
run torus_sphere_crease_dashed torus_sphere.obj 'crease 40\n' 8192 16384 32768
if [ "$turned_runs" -eq 0 ] || [ "$row_runs" -eq 0 ]; then
  bad "banded in columns $turned_runs times, in rows $row_runs times: both frames must be tried"
fi

echo "band_dashes: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
