# Models the tests generate, as Wavefront OBJ on standard output (sourced, not run): a torus
# and a sphere through a torus. band_dashes and the QEMU link test draw the same solids.
# Usage: torus_obj R r NU NV         a torus around the y axis, NU x NV quads
#        torus_sphere_obj            the 10 x 5 torus (R 1.5, r 0.5) with a 6 x 5 sphere through it
#        uv_sphere_obj R NS NT       a UV sphere around the y axis, NS segments, NT rings:
#                                    2 NS (NT - 1) triangles
#        pierced_tori_obj NU NV      three tori (R 1.5, r 0.5) around the y, z and x axes through
#                                    one another, each NU x NV quads: 6 NU NV triangles, a
#                                    closed mesh that pierces itself (600 280: 1,008,000)
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

# Three tori whose surfaces pass through one another (a mesh that pierces itself, as an
# assembly of overlapping parts does): torus k is torus_obj's turned by k cyclic shifts of the
# axes (a rotation, so each stays wound outward) and moved by (0.21 k, -0.13 k, 0.17 k), so no
# two share a plane of symmetry.
pierced_tori_obj() {
  awk -v nu="$1" -v nv="$2" 'BEGIN {
    pi = 3.14159265358979; R = 1.5; r = 0.5
    for (k = 0; k < 3; k++) {
      for (i = 0; i < nu; i++) for (j = 0; j < nv; j++) {
        u = 2 * pi * i / nu; v = 2 * pi * j / nv
        p[0] = (R + r * cos(v)) * cos(u); p[1] = r * sin(v); p[2] = (R + r * cos(v)) * sin(u)
        printf "v %.6f %.6f %.6f\n", p[(3 - k) % 3] + 0.21 * k, p[(4 - k) % 3] - 0.13 * k,
          p[(5 - k) % 3] + 0.17 * k
      }
      base = k * nu * nv
      for (i = 0; i < nu; i++) for (j = 0; j < nv; j++) {
        a = base + i * nv + j + 1; b = base + ((i + 1) % nu) * nv + j + 1
        c = base + ((i + 1) % nu) * nv + (j + 1) % nv + 1; d = base + i * nv + (j + 1) % nv + 1
        printf "f %d %d %d %d\n", a, d, c, b
      }
    }
  }'
}
