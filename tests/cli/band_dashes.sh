#!/usr/bin/env bash
# A hidden-line plot in bands draws the whole-model plot, dash for dash. For each
# solid (the 6 x 6 cubes of Figure 4, a torus, a sphere through a torus), hidden-dashed with
# outlines and hatching (the cubes also without hatching, as reported), `haloplot sim` plots the
# job whole and with arenas small enough for several bands; band_dashes_check
# (tests/tools/band_dashes_check.cpp, which reads the traces alone) compares the pen-down
# strokes, joined across the borders, with the whole-model trace's: every stroke end, every
# dash's included, within one step.
#   band_dashes.sh HALOPLOT BAND_DASHES_CHECK
set -u
tool="$1"
check="$2"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
pass=0 fail=0
ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAILED: $*" >&2; }
cd "$work"

"$tool" demo-scene --cubes 6 -o cubes6.obj || bad "demo-scene --cubes 6"
# A torus of 12 x 6 facets; the sphere through a torus of the firmware tests (10 x 5 and 6 x 5).
awk 'BEGIN {
  pi = 3.14159265358979; R = 1.5; r = 0.6; nu = 12; nv = 6
  for (i = 0; i < nu; i++) for (j = 0; j < nv; j++) {
    u = 2 * pi * i / nu; v = 2 * pi * j / nv
    printf "v %.6f %.6f %.6f\n", (R + r * cos(v)) * cos(u), r * sin(v), (R + r * cos(v)) * sin(u)
  }
  for (i = 0; i < nu; i++) for (j = 0; j < nv; j++) {
    a = i * nv + j + 1; b = ((i + 1) % nu) * nv + j + 1
    c = ((i + 1) % nu) * nv + (j + 1) % nv + 1; d = i * nv + (j + 1) % nv + 1
    printf "f %d %d %d %d\n", a, d, c, b
  }
}' > torus.obj
awk 'BEGIN {
  pi = 3.14159265358979
  R = 1.5; r = 0.5; nu = 10; nv = 5
  for (i = 0; i < nu; i++) for (j = 0; j < nv; j++) {
    u = 2 * pi * i / nu; v = 2 * pi * j / nv
    printf "v %.6f %.6f %.6f\n", (R + r * cos(v)) * cos(u), r * sin(v), (R + r * cos(v)) * sin(u)
  }
  for (i = 0; i < nu; i++) for (j = 0; j < nv; j++) {
    a = i * nv + j + 1; b = ((i + 1) % nu) * nv + j + 1
    c = ((i + 1) % nu) * nv + (j + 1) % nv + 1; d = i * nv + (j + 1) % nv + 1
    printf "f %d %d %d %d\n", a, d, c, b
  }
  base = nu * nv; cx = 1.5; cy = 0.1; cz = 0; s = 0.8; ns = 6; nt = 5
  printf "v %.6f %.6f %.6f\n", cx, cy + s, cz
  for (t = 1; t < nt; t++) for (k = 0; k < ns; k++) {
    th = pi * t / nt; ph = 2 * pi * k / ns
    printf "v %.6f %.6f %.6f\n", cx + s * sin(th) * cos(ph), cy + s * cos(th), cz + s * sin(th) * sin(ph)
  }
  printf "v %.6f %.6f %.6f\n", cx, cy - s, cz
  top = base + 1; bot = base + 2 + (nt - 1) * ns
  for (k = 0; k < ns; k++) printf "f %d %d %d\n", top, base + 2 + (k + 1) % ns, base + 2 + k
  for (t = 0; t < nt - 2; t++) for (k = 0; k < ns; k++) {
    a = base + 2 + t * ns + k; b = base + 2 + t * ns + (k + 1) % ns
    printf "f %d %d %d %d\n", a, b, b + ns, a + ns
  }
  for (k = 0; k < ns; k++) printf "f %d %d %d\n", bot, base + 2 + (nt - 2) * ns + k, base + 2 + (nt - 2) * ns + (k + 1) % ns
}' > torus_sphere.obj

# NAME SCENE EXTRA-KEYS ARENA...: the whole-model trace, then one banded trace per arena.
run() {
  local name="$1" scene="$2" extra="$3"
  shift 3
  printf 'scene %s\ndrawing hidden-dashed\nview 30,25\noutline on\n%beffects acceleration pen-servo\nkinematics corexy\n' \
    "$scene" "$extra" > "$name.job"
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
    out=$("$check" "$name.trace" "${name}_$arena.trace")
    rc=$?
    echo "$name, arena $arena ($bands bands): $out"
    if [ "$rc" -eq 0 ]; then ok; else bad "$name in $arena bytes ($bands bands) draws another picture"; fi
  done
}

run cubes6 cubes6.obj '' 32768
run cubes6_hatched cubes6.obj 'hatch 3 30 90\n' 32768 49152 65536
run torus torus.obj 'hatch 3 30 90\n' 16384 32768 65536
run torus_sphere torus_sphere.obj 'hatch 3 30 90\n' 16384 32768 65536

echo "band_dashes: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
