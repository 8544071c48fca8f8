#!/usr/bin/env python3
"""--simplify MM (core/motion/stroke_simplify.h), read back from the G-code with
tests/cli/stroke_quality.py's reader, none of the tool's code: a dense torus plotted with and
without it must draw the same strokes (as many, with the same ends, in the same order), every
point of each stroke as found must lie within MM of the simplified stroke, and the simplified
G-code must have fewer points. The bound check is then run at a quarter of MM and must fail:
it sees the points left out.

  stroke_simplify.py TOOL WORKDIR   (the model: a torus of 160 x 80 quads, written here)
"""
import math
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from stroke_quality import gcode_strokes  # noqa: E402

PER_MM = 80
TOL_MM = 0.2


def seg_dist(p, a, b):
    dx, dy = b[0] - a[0], b[1] - a[1]
    L2 = dx * dx + dy * dy
    t = 0 if L2 == 0 else max(0.0, min(1.0, ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / L2))
    return math.hypot(p[0] - a[0] - t * dx, p[1] - a[1] - t * dy)


def worst(found, simple):
    """The largest distance (steps) of a point of `found` from the matching simplified stroke;
    None when the strokes do not match."""
    if len(found) != len(simple):
        return None
    w = 0.0
    for f, s in zip(found, simple):
        if f[0] != s[0] or f[-1] != s[-1]:
            return None
        for p in f:
            w = max(w, min(seg_dist(p, a, b) for a, b in zip(s, s[1:])) if len(s) > 1 else
                    math.hypot(p[0] - s[0][0], p[1] - s[0][1]))
    return w


def write_torus(path, nu=160, nv=80, R=1.5, r=0.5):
    with open(path, "w") as o:
        for i in range(nu):
            for j in range(nv):
                u, v = 2 * math.pi * i / nu, 2 * math.pi * j / nv
                o.write("v %.6f %.6f %.6f\n" % ((R + r * math.cos(v)) * math.cos(u),
                                                (R + r * math.cos(v)) * math.sin(u), r * math.sin(v)))
        for i in range(nu):
            for j in range(nv):
                a, b = i * nv + j, ((i + 1) % nu) * nv + j
                c, d = ((i + 1) % nu) * nv + (j + 1) % nv, i * nv + (j + 1) % nv
                o.write("f %d %d %d %d\n" % (a + 1, b + 1, c + 1, d + 1))


def plot(tool, model, out, extra):
    cmd = [tool, "plot", model, "--mode", "hidden-removed", "--crease", "40", "--gcode", out] + extra
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit("FAIL: %s: %s" % (" ".join(cmd), r.stderr))
    return gcode_strokes(out, PER_MM)


def main():
    tool, work = sys.argv[1], sys.argv[2]
    os.makedirs(work, exist_ok=True)
    model = os.path.join(work, "torus.obj")
    write_torus(model)
    found = plot(tool, model, os.path.join(work, "found.gcode"), [])
    simple = plot(tool, model, os.path.join(work, "simple.gcode"), ["--simplify", str(TOL_MM)])
    # The page centres the pen-down box, which a left-out extreme point can move by a step:
    # the two drawings are compared with their first points put together.
    if found and simple:
        ox, oy = found[0][0][0] - simple[0][0][0], found[0][0][1] - simple[0][0][1]
        if abs(ox) > 1 or abs(oy) > 1:
            sys.exit("FAIL: the drawing moved by (%d, %d) steps" % (ox, oy))
        simple = [[(x + ox, y + oy) for x, y in st] for st in simple]
    w = worst(found, simple)
    if w is None:
        sys.exit("FAIL: the simplified plot's strokes are not the found ones (%d against %d, or "
                 "other ends)" % (len(simple), len(found)))
    n_found, n_simple = sum(map(len, found)), sum(map(len, simple))
    print("%d strokes: %d points as found, %d simplified; farthest point %.2f steps (bound %.1f)"
          % (len(found), n_found, n_simple, w, TOL_MM * PER_MM))
    bad = []
    if w > TOL_MM * PER_MM:
        bad.append("a point %.2f steps from the simplified stroke" % w)
    if n_simple >= n_found:
        bad.append("no point left out")
    if w <= TOL_MM * PER_MM / 4:
        bad.append("the check at a quarter of the tolerance passes: it cannot see what is left out")
    if bad:
        sys.exit("FAIL: " + "; ".join(bad))


if __name__ == "__main__":
    main()
