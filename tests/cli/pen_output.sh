#!/usr/bin/env bash
# CTest pen_output: the plot's files as a pen plotter takes them, read by
# tests/cli/pen_output_check.py (xml.etree and plain text, none of the tool's code).
#  - SVG layers: each layer's id number is its label's ("layer3" for "3 intersections", also
#    when a layer before it is empty), the layers' stroke colours differ pairwise, and the
#    HPGL's pen changes select the same numbers.
#  - G-code dialects: --gcode-flavor marlin writes every dwell as G4 P<integer milliseconds>,
#    1000 times the grbl file's seconds, and --gcode-header/--gcode-footer where docs/cli.md
#    says (the header right after G90, the footer after the last move, before the end).
#  - The summary on stderr is the file: its strokes are the G-code's pen-downs and its pen-up
#    travel the G-code's G0 travel from (0, 0) through the trip home, within 0.5 %, for assimp's
#    spider (when installed) and a generated torus, in every mode (haloed, all, hidden-removed,
#    hidden-dashed, hatched), and `sim`'s of a job in bands for the torus.
# Usage: pen_output.sh HALOPLOT
set -u
tool="$1"
here=$(cd "$(dirname "$0")" && pwd)
check="python3 $here/pen_output_check.py"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
pass=0 fail=0
expect() { if eval "$1" > out.txt 2>&1; then pass=$((pass + 1)); echo "ok: $(tail -1 out.txt)"; else fail=$((fail + 1)); echo "FAILED: $2: $(cat out.txt)"; fi; }

# shellcheck source=../support/model_files.sh
source "$here/../support/model_files.sh"  # torus_obj, box
torus_obj 1.5 0.5 24 12 > torus.obj
# Two pierced boxes, hidden-dashed, outlined and hatched: all five layers. Without
# intersections the third is empty and the hatching's id must still be layer4.
{ box 0 2 0 2 0 -2 1; box 0.7 2.6 0.4 2.5 -0.6 -2.7 9; } > pierced.obj
"$tool" plot pierced.obj --view 30,25 --mode hidden-dashed --outline --hatch 1 -o five.svg 2> /dev/null
expect "$check layers five.svg" "five layers: ids follow labels, colours distinct"
"$tool" plot pierced.obj --view 30,25 --mode hidden-dashed --outline --hatch 1 \
  --no-intersections -o gap.svg 2> /dev/null
expect "$check layers gap.svg" "a layer left out: the later ids keep their labels' numbers"
"$tool" plot pierced.obj --view 30,25 --mode hidden-dashed --outline --hatch 1 \
  --no-intersections --pause-between-layers -o gap.svg --hpgl gap.hpgl 2> /dev/null
expect "$check pens gap.svg gap.hpgl" "the HPGL's pens are the SVG's layer numbers"

# Dialects: the same plot in grbl and marlin, then with a header and a footer.
drawing="--mode hidden-removed --view 20,30"
# shellcheck disable=SC2086
"$tool" plot torus.obj $drawing --gcode grbl.gcode 2> /dev/null
# shellcheck disable=SC2086
"$tool" plot torus.obj $drawing --gcode marlin.gcode --gcode-flavor marlin 2> /dev/null
expect "$check dwells grbl.gcode marlin.gcode" "marlin dwells in integer ms, 1000 x grbl's seconds"
# shellcheck disable=SC2086
"$tool" plot torus.obj $drawing --gcode pen.gcode --pen-dwell 0.35 --gcode-flavor marlin 2> /dev/null
expect "grep -qx 'G4 P350' pen.gcode" "--pen-dwell 0.35 is G4 P350 in marlin"
for flavor in grbl marlin; do
  # shellcheck disable=SC2086
  "$tool" plot torus.obj $drawing --gcode hf_$flavor.gcode --gcode-flavor $flavor \
    --gcode-header 'M117 start\nG92 X0 Y0' --gcode-footer 'M117 done' 2> /dev/null
  expect "$check around hf_$flavor.gcode 'M117 start\nG92 X0 Y0' 'M117 done'" \
    "$flavor: the header after G90, the footer at the end"
done

# The same as job keys: `sim` writes plot's bytes. Bad values are refused by the option's name.
printf 'scene torus.obj\ndrawing hidden-removed\nview 20,30\ngcode-flavor marlin\n' > m.job
printf 'gcode-header M117 start\\nG92 X0 Y0\ngcode-footer M117 done\n' >> m.job
"$tool" sim m.job -o m.trace --gcode m.gcode 2> /dev/null
expect "cmp -s m.gcode hf_marlin.gcode" "the job's gcode-flavor, -header and -footer keys"
refused() {  # WHAT PATTERN OPTIONS...
  local what="$1" pattern="$2"
  shift 2
  # shellcheck disable=SC2086
  "$tool" plot torus.obj $drawing --gcode x.gcode "$@" 2> err.txt
  local rc=$?
  expect "[ $rc -ne 0 ] && grep -q -- \"$pattern\" err.txt && [ ! -e x.gcode ]" "$what: $(cat err.txt)"
}
refused "an unknown dialect" "--gcode-flavor 'smoothie' must be grbl or marlin" \
  --gcode-flavor smoothie
refused "marlin's angle" "--servo-down '200' must be an angle in \[0, 180\]" \
  --gcode-flavor marlin --servo-down 200
refused "an up angle in grbl" "--servo-up is for --gcode-flavor marlin" --servo-up 90

# The summary against the G-code it describes.
summary() {  # NAME MODEL OPTIONS...
  local name="$1" model="$2"
  shift 2
  "$tool" plot "$model" "$@" --gcode "$name.gcode" 2> "$name.err"
  expect "$check summary $name.gcode $name.err" "$name: the summary is the G-code's"
}
spider=/usr/share/assimp/models/OBJ/spider.obj
models="torus.obj"
[ -r "$spider" ] && models="$models $spider" || echo "note: $spider not installed (assimp-testmodels)"
for model in $models; do
  base=$(basename "$model" .obj)
  summary "${base}_removed" "$model" --mode hidden-removed
  summary "${base}_dashed" "$model" --mode hidden-dashed
  summary "${base}_haloed" "$model" --halo 40
  summary "${base}_hatched" "$model" --mode hidden-removed --hatch 1
  summary "${base}_all" "$model" --mode all
done

# In bands: `sim` of a job with an arena writes the G-code and says the same summary.
banded() {  # NAME MODEL JOB-LINES
  local name="$1" model="$2"
  printf 'scene %s\nview 20,30\narena 65536\n%b' "$model" "$3" > "$name.job"
  "$tool" sim "$name.job" -o "$name.trace" --gcode "$name.gcode" 2> "$name.err"
  expect "$check summary $name.gcode $name.err" "$name in bands: the summary is the G-code's"
}
banded torus_bands_removed torus.obj 'drawing hidden-removed\n'
banded torus_bands_dashed torus.obj 'drawing hidden-dashed\n'
banded torus_bands_hatched torus.obj 'drawing hidden-removed\nhatch 1\n'
banded torus_bands_haloed torus.obj 'halo 40\n'

echo "pen_output: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
