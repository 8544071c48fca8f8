# Models the tests generate, as Wavefront OBJ on standard output (sourced, not run): a torus
# and a sphere through a torus. band_dashes and the QEMU link test draw the same solids.
# Usage: torus_obj R r NU NV         a torus around the y axis, NU x NV quads
#        torus_sphere_obj            the 10 x 5 torus (R 1.5, r 0.5) with a 6 x 5 sphere through it
#        uv_sphere_obj R NS NT       a UV sphere around the y axis, NS segments, NT rings:
#                                    2 NS (NT - 1) triangles
torus_obj() {
  awk -v R="$1" -v r="$2" -v nu="$3" -v nv="$4" 'BEGIN {
    pi = 3.14159265358979
    for (i = 0; i < nu; i++) for (j = 0; j < nv; j++) {
      u = 2 * pi * i / nu; v = 2 * pi * j / nv
      printf "v %.6f %.6f %.6f\n", (R + r * cos(v)) * cos(u), r * sin(v), (R + r * cos(v)) * sin(u)
    }
    for (i = 0; i < nu; i++) for (j = 0; j < nv; j++) {
      a = i * nv + j + 1; b = ((i + 1) % nu) * nv + j + 1
      c = ((i + 1) % nu) * nv + (j + 1) % nv + 1; d = i * nv + (j + 1) % nv + 1
      printf "f %d %d %d %d\n", a, d, c, b
    }
  }'
}
torus_sphere_obj() {
  torus_obj 1.5 0.5 10 5
  awk 'BEGIN {
    pi = 3.14159265358979
    base = 50; cx = 1.5; cy = 0.1; cz = 0; s = 0.8; ns = 6; nt = 5
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
    for (k = 0; k < ns; k++)
      printf "f %d %d %d\n", bot, base + 2 + (nt - 2) * ns + k, base + 2 + (nt - 2) * ns + (k + 1) % ns
  }'
}

uv_sphere_obj() {
  awk -v s="$1" -v ns="$2" -v nt="$3" 'BEGIN {
    pi = 3.14159265358979
    printf "v 0 %.6f 0\n", s
    for (t = 1; t < nt; t++) for (k = 0; k < ns; k++) {
      th = pi * t / nt; ph = 2 * pi * k / ns
      printf "v %.6f %.6f %.6f\n", s * sin(th) * cos(ph), s * cos(th), s * sin(th) * sin(ph)
    }
    printf "v 0 %.6f 0\n", -s
    top = 1; bot = 2 + (nt - 1) * ns
    for (k = 0; k < ns; k++) printf "f %d %d %d\n", top, 2 + (k + 1) % ns, 2 + k
    for (t = 0; t < nt - 2; t++) for (k = 0; k < ns; k++) {
      a = 2 + t * ns + k; b = 2 + t * ns + (k + 1) % ns
      printf "f %d %d %d %d\n", a, b, b + ns, a + ns
    }
    for (k = 0; k < ns; k++)
      printf "f %d %d %d\n", bot, 2 + (nt - 2) * ns + k, 2 + (nt - 2) * ns + (k + 1) % ns
  }'
}

# An axis-aligned box as OBJ lines: box x0 x1 y0 y1 z0 z1 FIRST-VERTEX (its vertices are numbered
# from FIRST-VERTEX, so boxes can be concatenated into one file); 8 vertices and 6 faces,
# counter-clockwise seen from outside when x0 < x1, y0 < y1 and z0 > z1 as the tests write them.
box() {  # x0 x1 y0 y1 z0 z1 first-vertex: 8 vertices and 6 faces, counter-clockwise outside
  local x0=$1 x1=$2 y0=$3 y1=$4 z0=$5 z1=$6 b=$7
  for y in $y0 $y1; do for z in $z0 $z1; do for x in $x0 $x1; do echo "v $x $y $z"; done; done; done
  echo "f $b $((b + 2)) $((b + 3)) $((b + 1))"
  echo "f $((b + 4)) $((b + 5)) $((b + 7)) $((b + 6))"
  echo "f $b $((b + 1)) $((b + 5)) $((b + 4))"
  echo "f $((b + 2)) $((b + 6)) $((b + 7)) $((b + 3))"
  echo "f $b $((b + 4)) $((b + 6)) $((b + 2))"
  echo "f $((b + 1)) $((b + 3)) $((b + 7)) $((b + 5))"
}
