#!/usr/bin/env bash
# CTest plot_weld_hint: what `plot` says about open shells and shells that cannot be oriented,
# on meshes whose answer is known from how they were made:
# - a cube whose six faces each have their own four corners, each face's corners moved by a
#   known offset along x (face k by k * 0.00013): the message names a --weld EPS that closes
#   all 24 open sides, at least the largest distance between two copies of one cube corner
#   (what a weld must join) and below 1/8 of the cube's side; the plot with that --weld is a
#   closed solid (no message, no boundary edge);
# - an open hemisphere (a rim and no other open side): "open as made", no --weld named;
# - a tetrahedron with a fin on one edge (a side on three faces): the message names the line
#   of one of the three faces on that side, and that side's two ends;
# - a book of three open pages whose spines are 0.001 apart: the --weld named does no harm
#   (joining all three would put the spine on three faces), and --weld 0.01, which does, is
#   told so.
# Usage: plot_weld_hint.sh HALOPLOT
set -u
tool="$1"
# shellcheck source=../support/checks.sh
. "$(cd "$(dirname "$0")" && pwd)/../support/checks.sh"
cd "$work" || exit 1

# The split cube: faces as (axis, side); face k's four corners shifted by k * D in x.
awk -v D=0.00013 'BEGIN {
  n = 0
  for (k = 0; k < 6; k++) {
    axis = int(k / 2); side = k % 2
    for (c = 0; c < 4; c++) {
      u = (c == 1 || c == 2); w = (c >= 2)
      if (axis == 0) { x = side; y = u; z = w }
      if (axis == 1) { x = u; y = side; z = w }
      if (axis == 2) { x = u; y = w; z = side }
      printf "v %.6f %.6f %.6f\n", x + k * D, y, z
    }
    printf "f %d %d %d %d\n", 4 * k + 1, 4 * k + 2, 4 * k + 3, 4 * k + 4
  } }' > split_cube.obj
# What a weld must join: the largest distance between two copies of one cube corner (the
# vertices rounded back to their cube corner), from the file itself.
need=$(awk '$1 == "v" { key = sprintf("%d %d %d", $2 + 0.5, $3 + 0.5, $4 + 0.5)
  if (key in lo) { if ($2 < lo[key]) lo[key] = $2; if ($2 > hi[key]) hi[key] = $2 }
  else lo[key] = hi[key] = $2 }
  END { m = 0; for (k in lo) if (hi[k] - lo[k] > m) m = hi[k] - lo[k]; printf "%.6f", m }' split_cube.obj)
"$tool" plot split_cube.obj --mode hidden-removed -o cube.svg 2> err.txt
eps=$(grep -o -- '--weld [0-9.e-]* would close all 24 open sides' err.txt | awk '{ print $2 }')
if [ -n "$eps" ] && awk -v e="$eps" -v n="$need" 'BEGIN { exit !(e >= n && e < 0.125) }'; then
  ok "the split cube: --weld $eps (at least the $need its copies of a corner lie apart, under 1/8 of a side) closes all 24 open sides"
else
  bad "the split cube: no --weld EPS in [$need, 0.125) closing all 24 open sides: $(cat err.txt)"
fi
if [ -n "$eps" ] && "$tool" plot split_cube.obj --mode hidden-removed --weld "$eps" -o welded.svg --stats 2> err.txt &&
   ! grep -q "^haloplot: " err.txt && grep -q "^boundary_edges=0$" err.txt; then
  ok "the split cube with --weld $eps is a closed solid"
else
  bad "the split cube with --weld '$eps' is not a closed solid: $(cat err.txt)"
fi

# The hemisphere: 6 rings of 16 quads from the pole down to the equator, open at the rim.
awk 'BEGIN { pi = 3.14159265358979; R = 6; S = 16
  print "v 0 0 1"
  for (r = 1; r <= R; r++) for (s = 0; s < S; s++) {
    t = pi / 2 * r / R; p = 2 * pi * s / S
    printf "v %.6f %.6f %.6f\n", sin(t) * cos(p), sin(t) * sin(p), cos(t) }
  for (s = 0; s < S; s++) printf "f 1 %d %d\n", 2 + s, 2 + (s + 1) % S
  for (r = 1; r < R; r++) for (s = 0; s < S; s++) {
    a = 2 + (r - 1) * S + s; b = 2 + (r - 1) * S + (s + 1) % S
    printf "f %d %d %d %d\n", a, a + S, b + S, b } }' > hemisphere.obj
"$tool" plot hemisphere.obj --mode hidden-removed -o hemisphere.svg 2> err.txt
if grep -q "hemisphere.obj: its shell is open as made: no other open side's corner lies within 1/8 of a side's length, so no weld closes it; faces hide from both sides, so the hidden lines are right" err.txt &&
   ! grep -qF -- "--weld" err.txt; then
  ok "the hemisphere is open as made, no --weld named"
else
  bad "the hemisphere: $(cat err.txt)"
fi
# --mode all hides nothing: the open shell changes nothing it draws, and is not said.
if "$tool" plot hemisphere.obj --mode all -o hemisphere_all.svg 2> err.txt && [ ! -s err.txt ]; then
  ok "--mode all says nothing of the hemisphere's open shell"
else
  bad "--mode all on the hemisphere: $(cat err.txt)"
fi

# The fin: a tetrahedron and a triangle on its edge from vertex 1 to vertex 2; comment lines
# put the faces on known lines.
cat > fin.obj << 'EOF'
v 0 0 0
v 1 0 0
v 0 1 0
v 0 0 1
v 0.5 -1 0.5
# the tetrahedron
f 1 3 2
f 1 2 4
f 2 3 4
# the fin
f 1 5 2
f 1 3 4
EOF
fin_lines=$(awk '$1 == "f" { has1 = has2 = 0; for (i = 2; i <= NF; i++) { has1 += $i == 1; has2 += $i == 2 }
  if (has1 && has2) print NR }' fin.obj | tr '\n' ' ')
"$tool" plot fin.obj --mode hidden-removed -o fin.svg 2> err.txt
line=$(grep -o 'fin.obj: its shell cannot be oriented: a side on 3 faces from ([^)]*) to ([^)]*), of the face on line [0-9]*' err.txt | sed 's/.* //')
ends=$(grep -o 'a side on 3 faces from ([^)]*) to ([^)]*)' err.txt | sed 's/.*from //')
if [ -n "$line" ] && [[ " $fin_lines" == *" $line "* ]] &&
   { [ "$ends" = "(0, 0, 0) to (1, 0, 0)" ] || [ "$ends" = "(1, 0, 0) to (0, 0, 0)" ]; }; then
  ok "the fin: the side on three faces, $ends, named on line $line (its faces are on lines $fin_lines)"
else
  bad "the fin: not the side from (0, 0, 0) to (1, 0, 0) at one of lines $fin_lines: $(cat err.txt)"
fi

# A book of three open pages on one spine, each page's spine 0.001 farther along x: a weld
# that joins all three spines puts the spine on three faces. What the message names must not:
# fewer open sides (of 12), no side on three faces, no shell that cannot be oriented. A weld
# asked for that does (0.01) is told it leaves more to mend than the default weld.
awk 'BEGIN { pi = 3.14159265358979
  for (k = 0; k < 3; k++) { a = 2 * pi * k / 3; d = k * 0.001
    printf "v %.6f 0 0\nv %.6f 0 1\nv %.6f %.6f 1\nv %.6f %.6f 0\n", d, d, cos(a), sin(a), cos(a), sin(a)
    printf "f %d %d %d %d\n", 4 * k + 1, 4 * k + 2, 4 * k + 3, 4 * k + 4 } }' > book.obj
"$tool" plot book.obj --mode hidden-removed -o book.svg 2> err.txt
book_eps=$(grep -o -- '--weld [0-9.e-]* would close' err.txt | awk '{ print $2 }')
if [ -n "$book_eps" ] &&
   "$tool" plot book.obj --mode hidden-removed --weld "$book_eps" -o book.svg --stats 2> err2.txt &&
   awk -F= '$1 == "boundary_edges" { b = $2 } $1 == "nonmanifold_edges" { n = $2 }
     END { exit !(b != "" && b < 12 && n == 0) }' err2.txt && ! grep -q "cannot be oriented" err2.txt; then
  ok "the book: --weld $book_eps closes open sides and puts no side on three faces"
else
  bad "the book: the weld named ('$book_eps') does harm or nothing: $(cat err.txt err2.txt 2> /dev/null)"
fi
"$tool" plot book.obj --mode hidden-removed --weld 0.01 -o book.svg 2> err.txt
if grep -q "book.obj: --weld 0.01 leaves more to mend than the default weld (no --weld): 1 side on 3+ faces (the default: 0)" err.txt; then
  ok "the book: --weld 0.01 is told it leaves more to mend than the default weld"
else
  bad "the book: --weld 0.01 is not told it did worse: $(cat err.txt)"
fi

echo "plot_weld_hint: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
