#!/ usr / bin / env python3
"""Hatching across a smooth region is one stroke per line, read from the SVG a user gets
(xml.etree and plain arithmetic, none of the tool's code).

Two smooth shapes, each seen whole and convex on paper, so every hatch line crosses what is
seen of it in one piece: a closed UV sphere, and an open shallow dome (an open mesh: both
sides of its faces hide). Each is plotted `--mode hidden-removed --crease 40 --hatch 2,30,0`
(one region, one direction) with `--min-stroke 0`, so no short stroke is dropped and hidden.
Every hatch line must come out as exactly one stroke: a gap of a single step anywhere along it
(a short piece across a triangle's corner left out, or a sliver hidden by a neighbouring face
through the rounding of the line's ends) splits it in two.

  hatch_smooth.py TOOL WORKDIR [control]

`control` cuts the longest hatch stroke of each plot in two, a step apart, and passes only if
the check then fails for every shape.
"""
import math
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from control_verdict import verdict  # noqa: E402
from hatch_regions import write_obj  # noqa: E402
from stroke_quality import svg_layer_paths  # noqa: E402

PER_MM = 80
SPACING_MM = 2


def sphere(n=96, m=48, r=30.0):
    """A closed UV sphere: rings of n corners, the poles' fans as triangles."""
    v = [(0.0, 0.0, r)]
    for i in range(1, m):
        a = math.pi * i / m
        v += [(r * math.sin(a) * math.cos(2 * math.pi * k / n),
               r * math.sin(a) * math.sin(2 * math.pi * k / n), r * math.cos(a)) for k in range(n)]
    v.append((0.0, 0.0, -r))
    south = len(v) - 1

    def ring(i, k):
        return 1 + (i - 1) * n + k % n

    f = [(0, ring(1, k), ring(1, k + 1)) for k in range(n)]
    for i in range(1, m - 1):
        f += [(ring(i, k), ring(i + 1, k), ring(i + 1, k + 1), ring(i, k + 1)) for k in range(n)]
    f += [(south, ring(m - 1, k + 1), ring(m - 1, k)) for k in range(n)]
    return v, f


def dome(n=96, m=40, r=40.0, h=6.0):
    """An open shallow cap z = h (1 - (x^2 + y^2) / r^2) over a disk: a centre, m rings."""
    v = [(0.0, 0.0, h)]
    for i in range(1, m + 1):
        s = r * i / m
        v += [(s * math.cos(2 * math.pi * k / n), s * math.sin(2 * math.pi * k / n),
               h * (1 - (s / r) ** 2)) for k in range(n)]

    def ring(i, k):
        return 1 + (i - 1) * n + k % n

    f = [(0, ring(1, k), ring(1, k + 1)) for k in range(n)]
    for i in range(1, m):
        f += [(ring(i, k), ring(i + 1, k), ring(i + 1, k + 1), ring(i, k + 1)) for k in range(n)]
    return v, f


def hatch_strokes(path):
    """The hatching layer's strokes, points in steps."""
    for label, strokes in svg_layer_paths(path):
        if "hatching" in label:
            return [[(x * PER_MM, y * PER_MM) for x, y in s] for s in strokes if len(s) >= 2]
    return []


def strokes_per_line(strokes):
    """Strokes grouped by the hatch line they lie on: the lines' normal from the longest
    stroke's direction, lines told apart by offsets more than half a spacing apart."""
    a, b = max(strokes, key=lambda s: math.dist(s[0], s[-1])), None
    a, b = a[0], a[-1]
    d = math.dist(a, b)
    nx, ny = -(b[1] - a[1]) / d, (b[0] - a[0]) / d
    offsets = sorted(sum(nx * x + ny * y for x, y in s) / len(s) for s in strokes)
    lines, last = [], None
    for o in offsets:
        if last is None or o - last > SPACING_MM * PER_MM / 2:
            lines.append(0)
        lines[-1] += 1
        last = o
    return lines


def check(name, strokes):
    lines = strokes_per_line(strokes)
    split = sum(1 for c in lines if c > 1)
    print("%s: %d hatch strokes on %d lines, %d lines in more than one stroke"
          % (name, len(strokes), len(lines), split))
    if len(lines) < 15:
        sys.exit("FAIL: %s: only %d hatch lines: the shape was not hatched as meant" % (name,
                                                                                      len(lines)))
    return split == 0


def cut_longest(strokes):
    """The longest stroke cut in two a step apart at its middle point (the control's fault)."""
    i = max(range(len(strokes)), key=lambda k: len(strokes[k]))
    s = strokes[i]
    mid = len(s) // 2
    (x0, y0), (x1, y1) = s[mid - 1], s[mid]
    d = math.dist(s[mid - 1], s[mid]) or 1
    return strokes[:i] + [s[:mid], [(x0 + (x1 - x0) / d, y0 + (y1 - y0) / d)] + s[mid:]] + \
        strokes[i + 1:]


def main():
    tool, work = sys.argv[1], sys.argv[2]
    control = len(sys.argv) > 3 and sys.argv[3] == "control"
    os.makedirs(work, exist_ok=True)
    failed = []
    for name, (v, f), view in (("sphere", sphere(), "30,25"), ("dome", dome(), "30,60")):
        base = os.path.join(work, name)
        write_obj(base + ".obj", v, f)
        cmd = [tool, "plot", base + ".obj", "--up", "z", "--view", view, "--mode",
               "hidden-removed", "--crease", "40", "--hatch", "%d,30,0" % SPACING_MM,
               "--min-stroke", "0", "-o", base + ".svg"]
        r = subprocess.run(cmd, capture_output=True, text=True)
        if r.returncode != 0:
            sys.exit("FAIL: %s: %s" % (" ".join(cmd), r.stderr))
        strokes = hatch_strokes(base + ".svg")
        if not strokes:
            sys.exit("FAIL: %s: no hatching layer in %s.svg" % (name, base))
        if not check(name, cut_longest(strokes) if control else strokes):
            failed.append(name)
    verdict(control, failed, 2, "a hatch line cut in two", "hatch lines in more than one stroke")


if __name__ == "__main__":
    main()
