#!/usr/bin/env bash
# Pen-up travel of a solid plotted in bands, measured in this run by `haloplot sim --stats`
# (pen_up_length, plot steps): 10 x 10 cubes hidden-dashed and hatched, without and with
# outlines (the demo-style job), in 64 KB, against the same conductor given room for one band
# (arena 256 MB) and against the whole-model plot (no arena). A band is a strip the pen crosses
# from side to side; the drawing is wider than tall, so the conductor turns the page a quarter
# and its strips are columns of the page, each crossed along the shorter side; and a line a
# border cuts (hatching, outlines) is drawn on across it, not lifted there. When last
# measured: 1.21x and 1.21x of one band's in 10 bands each (0.80x of the whole-model plot's);
# in strips of the page's rows 1.33x and 1.37x, without the serpentine 1.25x and 1.26x: the
# limit, 1.24x, fails both (the aim is 1.3x). Also counted: the spots where the banded plot
# lifts the pen and later puts it down on the same spot and the whole-model plot does not
# (from the G-code): 35 and 45, limit 55; 77 and 75 without the join at the border.
#   band_pen_up.sh HALOPLOT
set -u
tool="$1"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
pass=0 fail=0
cd "$work"

"$tool" demo-scene --cubes 10 -o c10.obj || { echo "FAILED: demo-scene --cubes 10"; exit 1; }
stat() { sed -n "s/^$2=//p" "$1" | head -1; }

# NAME EXTRA-KEYS LIMIT: the plot whole, in one band and in 64 KB; banded / one band at most
# LIMIT (thousandths).
run() {
  local name="$1" extra="$2" limit="$3"
  printf 'scene c10.obj\ndrawing hidden-dashed\nview 30,25\ndash 2 1\n%bhatch 3 30 90\nkinematics corexy\n' \
    "$extra" > "$name.job"
  { cat "$name.job"; echo "arena 268435456"; } > "${name}_one.job"
  { cat "$name.job"; echo "arena 65536"; } > "${name}_arena.job"
  local j
  for j in "$name" "${name}_one" "${name}_arena"; do
    if ! "$tool" sim "$j.job" -o "$j.trace" --gcode "$j.gcode" --stats 2> "$j.stats"; then
      echo "FAILED: $j: the plot failed"
      fail=$((fail + 1))
      return
    fi
  done
  local whole one banded bands one_bands ratio
  whole=$(stat "$name.stats" pen_up_length)
  one=$(stat "${name}_one.stats" pen_up_length)
  one_bands=$(stat "${name}_one.stats" bands)
  banded=$(stat "${name}_arena.stats" pen_up_length)
  bands=$(stat "${name}_arena.stats" bands)
  ratio=$((1000 * banded / one))
  echo "$name: pen-up in one band $one, in 64 KB ($bands bands) $banded: $ratio/1000 of one" \
    "band's (limit $limit); the whole-model plot $whole: banded $((1000 * banded / whole))/1000"
  if [ "${one_bands:-0}" -eq 1 ] && [ "${bands:-0}" -ge 2 ] && [ "$ratio" -le "$limit" ]; then
    pass=$((pass + 1))
  else
    echo "FAILED: $name: banded pen-up travel $ratio/1000 of one band's, limit $limit" \
      "($one_bands and $bands bands)"
    fail=$((fail + 1))
  fi
  # A line a border cuts is drawn on across it, not lifted there and put down again later on
  # the same spot: the spots where the banded plot does that and the whole-model plot does not.
  local spots
  spots=$(awk 'FNR == 1 { f++ }
    { x = ""; y = ""
      for (i = 2; i <= NF; i++) { if ($i ~ /^X/) x = $i; if ($i ~ /^Y/) y = $i }
      if ($1 == "G0" || $1 == "G1") pos = x " " y
      if ($1 == "M5") { if (down) up[f, pos] = 1; down = 0 }
      if ($1 == "M3") { dn[f, pos] = 1; down = 1 } }
    END { for (k in up) { split(k, p, SUBSEP)
            if (p[1] == 2 && dn[k] && !(up[1, p[2]] && dn[1, p[2]])) n++ }
          print n + 0 }' "$name.gcode" "${name}_arena.gcode")
  echo "$name: $spots spots where the banded plot lifts the pen and puts it down again" \
    "(limit $spot_limit)"
  if [ "$spots" -le "$spot_limit" ]; then
    pass=$((pass + 1))
  else
    echo "FAILED: $name: $spots lift-and-put-down spots the whole-model plot has not"
    fail=$((fail + 1))
  fi
}
spot_limit=55

run hatched '' 1240
run demo_style 'outline on\n' 1240

echo "band_pen_up: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
