#!/usr/bin/env bash
# CTest plot_defaults: the defaults that fit the file (issue 45), each shown to matter by the
# same check failing with the feature turned off.
# (1) An STL is read Z-up: `plot X.stl` writes the same SVG and G-code bytes as `--up z`, and
#     not those of `--up y`, for assimp's Spider_binary.stl (if assimp-testmodels is installed)
#     and a generated float32 STL.
# (2) Faces flat but for the file's rounding: a float32 STL box whose faces are 4 x 4 grids of
#     triangles, turned off the axes, draws with no flags the ink of the same box as 6 quads
#     (OBJ, 9 decimals); with --crease exact (exactly coplanar only, the old default) it draws
#     the grids and differs.
# (3) Welding in every format: an OBJ triangle soup (every triangle its own corners, every other
#     copy 6 units off in the 6th decimal) draws with no flags the ink of its welded twin, in
#     hidden-removed and hidden-dashed; with --weld off and with --weld 0 (the same world
#     position only) it differs.
# Pictures are compared by tests/cli/defaults_models.py's SVG reader: total ink within 0.5 %
# and every point within one step in x and y of the other's strokes (two roundings to steps
# of nearly one point, printed to 0.001 mm: sqrt(2) * (1/80 + 0.001) mm).
# Usage: plot_defaults.sh HALOPLOT
set -u
tool="$1"
here=$(cd "$(dirname "$0")" && pwd)
models="python3 $here/defaults_models.py"
tol=0.0191
# shellcheck source=../support/expect.sh
. "$here/../support/expect.sh"

# (1) The up axis.
$models box-stl box.stl
stls=(box.stl)
spider=/usr/share/assimp/models/STL/Spider_binary.stl
if [ -r "$spider" ]; then stls+=("$spider"); else echo "note: $spider missing, generated STL only"; fi
for stl in "${stls[@]}"; do
  for up in default z y; do
    extra=()
    [ "$up" = default ] || extra=(--up "$up")
    "$tool" plot "$stl" --mode hidden-removed "${extra[@]}" -o "up_$up.svg" --gcode "up_$up.gcode" \
      2> /dev/null
  done
  name=$(basename "$stl")
  expect 'cmp -s up_default.svg up_z.svg && cmp -s up_default.gcode up_z.gcode' \
    "$name: no --up is --up z, byte for byte (SVG and G-code)"
  expect '! cmp -s up_default.svg up_y.svg && ! cmp -s up_default.gcode up_y.gcode' \
    "$name: and differs from --up y (the check can fail)"
done

# (2) Flat but for float32's rounding.
$models box-obj box.obj
"$tool" plot box.stl --mode hidden-removed -o grid.svg
"$tool" plot box.obj --up z --mode hidden-removed -o quads.svg
"$tool" plot box.stl --mode hidden-removed --crease exact -o exact.svg
expect "$models compare grid.svg quads.svg $tol" "the float32 grid box draws the quad box's ink"
expect "$models compare exact.svg quads.svg $tol; [ \$? -eq 1 ]" \
  "with --crease exact it draws its grids: differs"

# (3) An OBJ triangle soup welded by default.
$models soup soup.obj twin.obj
for mode in hidden-removed hidden-dashed; do
  "$tool" plot twin.obj --mode "$mode" -o "twin_$mode.svg"
  "$tool" plot soup.obj --mode "$mode" -o "soup_$mode.svg"
  expect "$models compare soup_$mode.svg twin_$mode.svg $tol" \
    "$mode: the soup draws its welded twin's ink"
  for weld in off 0; do
    "$tool" plot soup.obj --mode "$mode" --weld "$weld" -o "soup_$weld.svg" 2> /dev/null
    expect "$models compare soup_$weld.svg twin_$mode.svg $tol; [ \$? -eq 1 ]" \
      "$mode: with --weld $weld it differs"
  done
done

echo "plot_defaults: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
