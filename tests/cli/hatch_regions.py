#!/usr/bin/env python3
"""Hatching by region, read from the G-code a plotter gets (tests/cli/stroke_quality.py's
reader, none of the tool's code).

Two shapes, each written twice with the same float32 corners: once as a slicer or a 3-D
printing export writes it (a binary STL, every flat side split into triangles, a cap as a fan
of slivers from one rim corner), once with each flat side one polygon (an OBJ of quads and an
n-gon cap). Both are plotted `--mode hidden-removed --hatch 1`; the triangles must hatch in at
most 1.2 times the strokes of the polygons: faces joined by sides that are not drawn (flat but
for the rounding) hatch as one region with one family of lines, not a fan of directions.

  hatch_regions.py TOOL WORKDIR [control]

`control` plots the triangle files with `--crease exact` (faces count as one region only when
exactly coplanar, which rounded float32 corners of a turned box never are) and passes only if
the check then fails for every shape: it sees the hatching by triangle.
"""
import math
import os
import struct
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from control_verdict import verdict  # noqa: E402
from stroke_quality import gcode_strokes  # noqa: E402

LIMIT = 1.2


def f32(v):
    return struct.unpack("<f", struct.pack("<f", v))[0]


def turned(p, a_deg=23, b_deg=37):
    a, b = math.radians(a_deg), math.radians(b_deg)
    x, y, z = p
    x, y = x * math.cos(a) - y * math.sin(a), x * math.sin(a) + y * math.cos(a)
    y, z = y * math.cos(b) - z * math.sin(b), y * math.sin(b) + z * math.cos(b)
    return x, y, z


def box():
    """A box turned off the axes: its six sides as quads of float32 corners."""
    v = [tuple(f32(c) for c in turned((x * 30.3, y * 20.7, z * 10.1)))
         for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)]

    def i(x, y, z):
        return x * 4 + y * 2 + z

    quads = [(i(0, 0, 0), i(0, 1, 0), i(1, 1, 0), i(1, 0, 0)),
             (i(0, 0, 1), i(1, 0, 1), i(1, 1, 1), i(0, 1, 1)),
             (i(0, 0, 0), i(1, 0, 0), i(1, 0, 1), i(0, 0, 1)),
             (i(0, 1, 0), i(0, 1, 1), i(1, 1, 1), i(1, 1, 0)),
             (i(0, 0, 0), i(0, 0, 1), i(0, 1, 1), i(0, 1, 0)),
             (i(1, 0, 0), i(1, 1, 0), i(1, 1, 1), i(1, 0, 1))]
    tris = [t for q in quads for t in ((q[0], q[1], q[2]), (q[0], q[2], q[3]))]
    return v, quads, tris


def disk(n=240, r=40.0, h=5.0):
    """A flat cylinder turned off the axes: caps of n corners (fans of slivers from corner 0 as
    triangles), the side as n quads."""
    rim = [(r * math.cos(2 * math.pi * k / n), r * math.sin(2 * math.pi * k / n)) for k in range(n)]
    v = [tuple(f32(c) for c in turned((x, y, z), 11, 29)) for z in (h, 0.0) for x, y in rim]
    side = [(n + k, n + (k + 1) % n, (k + 1) % n, k) for k in range(n)]
    polys = [tuple(range(n)), tuple(range(2 * n - 1, n - 1, -1))] + side
    tris = [(0, k, k + 1) for k in range(1, n - 1)]
    tris += [(n, n + k + 1, n + k) for k in range(1, n - 1)]
    tris += [t for q in side for t in ((q[0], q[1], q[2]), (q[0], q[2], q[3]))]
    return v, polys, tris


def write_obj(path, v, faces):
    with open(path, "w") as o:
        for p in v:
            o.write("v %.9g %.9g %.9g\n" % p)
        for f in faces:
            o.write("f " + " ".join(str(k + 1) for k in f) + "\n")


def write_stl(path, v, tris):
    with open(path, "wb") as o:
        o.write(b"\0" * 80 + struct.pack("<I", len(tris)))
        for t in tris:
            o.write(struct.pack("<3f", 0, 0, 0))
            for k in t:
                o.write(struct.pack("<3f", *v[k]))
            o.write(b"\0\0")


def strokes(tool, model, out, extra):
    # Both files Z-up, so the two are seen alike.
    cmd = [tool, "plot", model, "--up", "z", "--mode", "hidden-removed", "--hatch", "1",
           "-o", out + ".svg", "--gcode", out + ".gcode"] + extra
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit("FAIL: %s: %s" % (" ".join(cmd), r.stderr))
    return len(gcode_strokes(out + ".gcode", 80))


def main():
    tool, work = sys.argv[1], sys.argv[2]
    control = len(sys.argv) > 3 and sys.argv[3] == "control"
    os.makedirs(work, exist_ok=True)
    failed = []
    for name, (v, polys, tris) in (("box", box()), ("disk", disk())):
        base = os.path.join(work, name)
        write_obj(base + "_polygons.obj", v, polys)
        write_stl(base + "_triangles.stl", v, tris)
        whole = strokes(tool, base + "_polygons.obj", base + "_polygons", [])
        split = strokes(tool, base + "_triangles.stl", base + "_triangles",
                        ["--crease", "exact"] if control else [])
        ratio = split / whole
        print("%s: %d strokes as triangles, %d as polygons (%.2f times)" % (name, split, whole,
                                                                            ratio))
        if ratio > LIMIT:
            failed.append(name)
    verdict(control, failed, 2, "--crease exact (hatching by triangle)",
            "hatched in over %.1f times the strokes" % LIMIT)


if __name__ == "__main__":
    main()
