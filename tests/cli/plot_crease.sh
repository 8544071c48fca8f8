#!/usr/bin/env bash
# CTest plot_crease: --crease above a smooth model's facet angle leaves out every edge between
# its faces, and the hidden-line modes still draw the model's contours (the outline): a torus of
# 24 x 12 facets (15 and 30 degrees apart) with --crease 40, hidden-removed and hidden-dashed,
# draws something, and every point it draws is a point of the same view's drawing with every
# edge kept (--crease off: the contours are mesh edges, at the same fit on the page), with
# fewer points (in the visible layer; hidden-dashed also dashes the hidden contours). `--mode
# all` works out no contours: it refuses, naming --crease, and says where --crease left bends
# out. Without --crease, a dense smooth model's hidden-line plot suggests it.
# Usage: plot_crease.sh HALOPLOT
set -u
tool="$1"
here=$(cd "$(dirname "$0")" && pwd)
# shellcheck source=../support/checks.sh
. "$(cd "$(dirname "$0")" && pwd)/../support/checks.sh"
cd "$work" || exit 1
# shellcheck source=../support/model_files.sh
source "$here/../support/model_files.sh"
torus_obj 1.5 0.6 24 12 > torus.obj

# The points of an SVG layer's paths (its label, e.g. "1 visible"), one "x,y" a line, sorted
# and unique.
points() {
  awk -v label="inkscape:label=\"$2\"" 'index($0, "<g ") { on = index($0, label) > 0 } on' "$1" |
    grep -o ' d="[^"]*"' | tr -s ' MLd="' '\n' | grep , | sort -u
}

for mode in hidden-removed hidden-dashed; do
  if ! "$tool" plot torus.obj --view 30,25 --mode "$mode" --crease off -o all_"$mode".svg 2> err.txt ||
     ! "$tool" plot torus.obj --view 30,25 --mode "$mode" --crease 40 -o smooth_"$mode".svg 2>> err.txt; then
    bad "$mode: a plot failed: $(cat err.txt)"
    continue
  fi
  points all_"$mode".svg "1 visible" > all.txt
  points smooth_"$mode".svg "1 visible" > smooth.txt
  n_all=$(wc -l < all.txt) n_smooth=$(wc -l < smooth.txt)
  extra=$(comm -13 all.txt smooth.txt | wc -l)
  if [ "$n_smooth" -gt 0 ] && [ "$extra" -eq 0 ] && [ "$n_smooth" -lt "$n_all" ]; then
    ok "$mode: --crease 40 draws $n_smooth points, all among the $n_all of --crease off"
  else
    bad "$mode: --crease 40 draws $n_smooth points, $extra not in --crease off's $n_all"
  fi
done
# Hidden-dashed draws the hidden parts of the contours dashed (the torus's back rim, its inner
# contour behind the tube), with no edge of the mesh left to carry them.
n_hidden=$(points smooth_hidden-dashed.svg "2 hidden" | wc -l)
if [ "$n_hidden" -gt 20 ]; then
  ok "hidden-dashed: --crease 40 dashes the hidden contours ($n_hidden points)"
else
  bad "hidden-dashed: --crease 40 draws $n_hidden points of hidden contours"
fi

# A torus whose tube faces are 20 degrees apart, seen from 20 degrees up: at its back a ring of
# faces is exactly edge-on, and the silhouette runs along it. Kira's outline (the boundary of
# what the picture covers) must be drawn whole in the visible layer; it once had a 21 mm gap
# there, the contour put on the edge-on face's far side.
torus_obj 3 1 36 18 > torus20.obj
for view in 30,20 10,20 30,25; do
  if ! "$tool" plot torus20.obj --view $view --mode hidden-removed --crease 40 --outline \
       -o edge_on.svg 2> err.txt; then
    bad "torus20 at $view: the plot failed: $(cat err.txt)"
  elif out=$(python3 "$here/outline_covered.py" edge_on.svg); then
    ok "torus20 at $view: $out"
  else
    bad "torus20 at $view: $out"
  fi
done

if "$tool" plot torus.obj --view 30,25 --mode all --crease 40 -o x.svg 2> err.txt; then
  bad "--mode all with every edge creased plotted (an empty drawing)"
elif grep -q -- "--crease 40" err.txt && [ ! -e x.svg ]; then
  ok "--mode all refuses: $(cat err.txt)"
else
  bad "--mode all: $(cat err.txt)"
fi

# Without --crease a dense smooth model draws every facet: the plot says so and names --crease.
# A torus of 200 x 60 facets (1.8 to 6 degrees apart: 24,000 edges, every one gentle) gets the
# hint; the same with --crease 40, and a torus of 24 x 12 facets (15 and 30 degrees apart), not.
torus_obj 1.5 0.6 200 60 > dense.obj
hint="join faces less than 10 degrees apart"
if ! "$tool" plot dense.obj --view 30,25 --mode hidden-removed -o d.svg 2> err.txt; then
  bad "the dense torus failed: $(cat err.txt)"
elif grep -q "$hint" err.txt && grep -q -- "--crease 40" err.txt; then
  ok "the dense torus without --crease: $(grep "$hint" err.txt)"
else
  bad "the dense torus without --crease gave no hint: $(cat err.txt)"
fi
for given in "dense.obj --crease 40" "torus.obj"; do
  # shellcheck disable=SC2086
  if "$tool" plot $given --view 30,25 --mode hidden-removed -o d.svg 2> err.txt &&
     ! grep -q "$hint" err.txt; then
    ok "no hint for $given"
  else
    bad "$given: $(cat err.txt)"
  fi
done

# The edges-only drawings (--mode all, haloed) work out no contours, so the hint, which leads
# to --crease, is not given there (following it lost the fresh user's outline silently), and a
# --crease that left out bends says the outline went with them. Flat diagonals alone (a box of
# triangles) are no bend: no word.
if "$tool" plot dense.obj --view 30,25 --mode all -o d.svg 2> err.txt && ! grep -q "$hint" err.txt; then
  ok "no hint for --mode all"
else
  bad "--mode all on the dense torus: $(cat err.txt)"
fi
note="no contours in their place"
for drawing in "--mode all" "--halo 40"; do
  # shellcheck disable=SC2086
  if "$tool" plot torus.obj --view 30,25 $drawing --crease 10 -o d.svg 2> err.txt &&
     [ "$(grep -c "$note" err.txt)" -eq 1 ] && grep -q -- "--crease 10 left out 96 edges" err.txt &&
     grep -q -- "--mode hidden-removed" err.txt; then
    ok "$drawing --crease 10 says the outline goes: $(grep "$note" err.txt)"
  else
    bad "$drawing --crease 10: $(cat err.txt)"
  fi
done
box 0 1 0 1 1 0 1 | awk '$1 == "f" { print "f", $2, $3, $4; print "f", $2, $4, $5; next } 1' > tri_box.obj
for given in "torus.obj --mode hidden-removed --crease 10" "tri_box.obj --halo 40 --crease 40" \
             "tri_box.obj --mode all --crease 40"; do
  # shellcheck disable=SC2086
  if "$tool" plot $given --view 30,25 -o d.svg 2> err.txt && ! grep -q "$note" err.txt; then
    ok "no contours note for $given"
  else
    bad "$given: $(cat err.txt)"
  fi
done

echo "plot_crease: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
