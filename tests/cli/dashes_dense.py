#!/usr/bin/env python3
"""Hidden lines of a dense mesh are dashed, read from the SVG a user gets (xml.etree and plain
arithmetic, none of the tool's code).

Two dense models whose hidden lines are curves of sides far shorter than a dash: a torus of
200 x 100 facets (its hidden outline is contour diagonals) and a cylinder of 360 sides (its
rims are drawn edges, the far one's back half hidden). Each is plotted `--mode hidden-dashed
--dash 2,1 --crease 40`. On paper a dash runs 2 to 2.83 mm (the pattern is the
page's, along the curve's longer axis: solid/modes.h, page_dashes), so at most 5 % of the hidden
layer's ink may lie in strokes longer than 3 mm, and the layer must hold at least one stroke for
every 4 mm of its ink (a dash and a gap, 3 to 4.24 mm of curve, less the crumbs dropped). Each
side dashed on its own drew the hidden curves nearly solid.

  dashes_dense.py TOOL WORKDIR [control]

`control` plots with `--dash 50,1` (dashes longer than any side, the old look) and passes only
if the check then fails for both models.
"""
import math
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from control_verdict import verdict  # noqa: E402
from hatch_regions import write_obj  # noqa: E402
from stroke_quality import svg_layer_paths  # noqa: E402

LONG_MM = 3.0
INK_PER_STROKE_MM = 4.0


def torus(n=200, m=100, big=1.5, small=0.6):
    v = []
    for i in range(n):
        a = 2 * math.pi * i / n
        for j in range(m):
            b = 2 * math.pi * j / m
            r = big + small * math.cos(b)
            v.append((r * math.cos(a), r * math.sin(a), small * math.sin(b)))
    f = [(i * m + j, ((i + 1) % n) * m + j, ((i + 1) % n) * m + (j + 1) % m, i * m + (j + 1) % m)
         for i in range(n) for j in range(m)]
    return v, f


def cylinder(n=360, r=30.0, h=40.0):
    v = [(r * math.cos(2 * math.pi * k / n), r * math.sin(2 * math.pi * k / n), z)
         for z in (0.0, h) for k in range(n)]
    f = [tuple(range(n - 1, -1, -1)), tuple(range(n, 2 * n))]
    f += [(k, (k + 1) % n, n + (k + 1) % n, n + k) for k in range(n)]
    return v, f


def hidden_strokes(path):
    """The hidden layer's strokes' lengths in mm."""
    for label, strokes in svg_layer_paths(path):
        if "hidden" in label:
            return [sum(math.dist(s[i], s[i + 1]) for i in range(len(s) - 1))
                    for s in strokes if len(s) >= 2]
    return []


def main():
    tool, work = sys.argv[1], sys.argv[2]
    control = len(sys.argv) > 3 and sys.argv[3] == "control"
    os.makedirs(work, exist_ok=True)
    failed = []
    for name, (v, f), extra in (("torus", torus(), ["--crease", "40"]),
                                ("cylinder", cylinder(), ["--crease", "40"])):
        base = os.path.join(work, name)
        write_obj(base + ".obj", v, f)
        cmd = [tool, "plot", base + ".obj", "--up", "z", "--view", "30,25", "--mode",
               "hidden-dashed", "--dash", "50,1" if control else "2,1", "-o", base + ".svg"]
        r = subprocess.run(cmd + extra, capture_output=True, text=True)
        if r.returncode != 0:
            sys.exit("FAIL: %s: %s" % (" ".join(cmd + extra), r.stderr))
        lengths = hidden_strokes(base + ".svg")
        ink = sum(lengths)
        if ink < 50:
            sys.exit("FAIL: %s: %.1f mm of hidden lines: the model was not drawn as meant"
                     % (name, ink))
        long_ink = sum(x for x in lengths if x > LONG_MM)
        print("%s: %d hidden strokes, %.0f mm of ink, %.1f %% of it in strokes over %.0f mm, "
              "one stroke per %.2f mm" % (name, len(lengths), ink, 100 * long_ink / ink, LONG_MM,
                                          ink / len(lengths)))
        if long_ink > 0.05 * ink or ink / len(lengths) > INK_PER_STROKE_MM:
            failed.append(name)
    verdict(control, failed, 2, "dashes of 50 mm (hidden lines nearly solid)",
            "hidden lines not dashed")


if __name__ == "__main__":
    main()
