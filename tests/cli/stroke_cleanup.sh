#!/usr/bin/env bash
# The strokes a plot hands the pen, read back from its SVG and G-code by an independent reader
# (tests/cli/stroke_quality.py): assimp's test models in the haloed and hidden-line modes,
# default flags, must plot no zero-length stroke, at most 1 % of strokes under 0.2 mm and at
# most 5 mm drawn twice within a layer. `control` plots the same with the clean-up off
# (--no-cleanup --min-stroke 0) and passes only if every one of the three checks then fails on
# some plot: the checks see what the clean-up removes. Skipped (77) without assimp-testmodels.
set -u
tool="$1" models="$2" control="${3:-}"
here="$(cd "$(dirname "$0")" && pwd)"
# shellcheck source=../support/checks.sh
. "$here/../support/checks.sh"
[ -d "$models/OBJ" ] || { echo "no assimp models in $models: skipped"; exit 77; }
cd "$work"
flags=()
[ "$control" = control ] && flags=(--no-cleanup --min-stroke 0)
dots=0 crumbs=0 twice=0
for f in OBJ/spider.obj STL/Spider_binary.stl OBJ/WusonOBJ.obj PLY/Wuson.ply OBJ/regr01.obj; do
  i=0
  for mode in "--halo 60" "--mode hidden-removed" "--mode hidden-dashed" \
    "--mode hidden-removed --hatch 1"; do
    i=$((i + 1))
    out="$(basename "$f").$i"
    # shellcheck disable=SC2086
    if ! "$tool" plot "$models/$f" $mode -o "$out.svg" --gcode "$out.gcode" "${flags[@]}" \
      2> "$out.err"; then
      bad "$f $mode: plot failed: $(cat "$out.err")"
      continue
    fi
    result=$(python3 "$here/stroke_quality.py" check "$out.svg" "$out.gcode" 80)
    if [ $? -eq 0 ]; then
      ok
    elif [ "$control" = control ]; then
      echo "$f $mode (clean-up off): $result"
      case "$result" in *zero-length*) dots=1 ;; esac
      case "$result" in *"strokes under"*) crumbs=1 ;; esac
      case "$result" in *"drawn twice"*) twice=1 ;; esac
    else
      bad "$f $mode: $result"
    fi
  done
done
if [ "$control" = control ]; then
  pass=0
  expect '[ $dots = 1 ]' "with the clean-up off, no plot had a zero-length stroke"
  expect '[ $crumbs = 1 ]' "with the clean-up off, no plot had over 1 % crumbs"
  expect '[ $twice = 1 ]' "with the clean-up off, no plot drew over 5 mm twice"
fi
echo "stroke_cleanup${control:+ ($control)}: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
