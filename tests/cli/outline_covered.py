#!/usr/bin/env python3
"""Is the picture's outline drawn? Every point of the SVG's "5 outlines" layer (Kira's outline:
the boundary of what the picture covers), sampled every 0.05 mm along its segments, must lie
within TOL mm of a segment of the "1 visible" layer. Reads the SVG alone.
Usage: outline_covered.py FILE.svg [TOL]   (prints the uncovered length; exit 1 if any)"""
import math
import re
import sys


def layers(path):
    out, label = {}, None
    for line in open(path):
        m = re.search(r'<g [^>]*inkscape:label="([^"]*)"', line)
        if m:
            label = m.group(1)
            out.setdefault(label, [])
        for d in re.findall(r' d="([^"]*)"', line):
            pts = [tuple(map(float, p.split(","))) for p in re.findall(r"-?[\d.]+,-?[\d.]+", d)]
            out.setdefault(label, []).extend(zip(pts, pts[1:]))
    return out


def near(p, seg, tol):
    (ax, ay), (bx, by) = seg
    dx, dy = bx - ax, by - ay
    n = dx * dx + dy * dy
    t = 0 if n == 0 else max(0, min(1, ((p[0] - ax) * dx + (p[1] - ay) * dy) / n))
    return math.hypot(ax + t * dx - p[0], ay + t * dy - p[1]) <= tol


def main():
    tol = float(sys.argv[2]) if len(sys.argv) > 2 else 0.02
    ls = layers(sys.argv[1])
    visible, outline = ls.get("1 visible", []), ls.get("5 outlines", [])
    if not outline:
        print("no outline layer")
        return 1
    cell = 2.0
    grid = {}
    for s in visible:
        x0, x1 = sorted((s[0][0], s[1][0]))
        y0, y1 = sorted((s[0][1], s[1][1]))
        for cx in range(int(x0 // cell) - 1, int(x1 // cell) + 2):
            for cy in range(int(y0 // cell) - 1, int(y1 // cell) + 2):
                grid.setdefault((cx, cy), []).append(s)
    missing = 0.0
    for (a, b) in outline:
        length = math.hypot(b[0] - a[0], b[1] - a[1])
        steps = max(1, int(length / 0.05))
        for k in range(steps):
            t = (k + 0.5) / steps
            p = (a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]))
            if not any(near(p, s, tol) for s in grid.get((int(p[0] // cell), int(p[1] // cell)), [])):
                missing += length / steps
    print("%.2f mm of the outline not drawn in the visible layer" % missing)
    return 1 if missing > 0.1 else 0


sys.exit(main())
