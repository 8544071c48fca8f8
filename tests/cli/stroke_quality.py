#!/usr/bin/env python3
"""An independent reader of a plot's strokes for tests/cli/stroke_cleanup.sh: the SVG's paths
(xml.etree) and the G-code's moves (plain text), none of the tool's code.

  stroke_quality.py measure SVG GCODE STEPS_PER_MM
      prints `strokes= dots= crumbs= twice_mm=` for the plot: the SVG's and the G-code's
      strokes must agree in number; dots are pen-down strokes of length 0, crumbs strokes
      under 0.2 mm (both counted in the SVG and in the G-code, the larger reported), twice_mm
      the length drawn more than once within one SVG layer by collinear overlapping segments.
  stroke_quality.py check SVG GCODE STEPS_PER_MM
      the same, and fails unless dots = 0, crumbs <= 1 % of strokes and twice_mm <= 5.
"""
import math
import re
import sys
import xml.etree.ElementTree as ET

SVG = "{http://www.w3.org/2000/svg}"
INK = "{http://www.inkscape.org/namespaces/inkscape}"
CRUMB_MM = 0.2


def svg_layer_paths(path):
    """Each layer's label and strokes, as lists of points in mm as the file writes them."""
    root = ET.parse(path).getroot()
    layers = []
    for g in root.iter(SVG + "g"):
        if g.get(INK + "groupmode") != "layer":
            continue
        strokes = []
        for p in g.iter(SVG + "path"):
            for sub in re.split(r"(?=M)", p.get("d") or ""):
                nums = [float(v) for v in re.findall(r"-?\d+(?:\.\d+)?", sub)]
                if len(nums) >= 2:
                    strokes.append([(nums[i], nums[i + 1]) for i in range(0, len(nums) - 1, 2)])
        layers.append((g.get(INK + "label") or "", strokes))
    return layers


def svg_layers(path, per_mm):
    """Each layer's strokes as lists of points in whole steps (the files round mm to 1/1000,
    finer than a step, so rounding back recovers the step lattice)."""
    return [[[(round(x * per_mm), round(y * per_mm)) for x, y in s] for s in strokes]
            for _, strokes in svg_layer_paths(path)]


def gcode_strokes(path, per_mm):
    strokes, cur, pos = [], None, (0, 0)
    with open(path) as f:
        for line in f:
            word = line.split(";")[0].split()
            if not word:
                continue
            if word[0] in ("G0", "G00", "M5", "M0") or word[0].startswith("M280"):
                cur = None
            if word[0] in ("G0", "G1", "G00", "G01"):
                xy = dict((w[0], float(w[1:])) for w in word[1:] if w[0] in "XY")
                pos = (round(xy.get("X", pos[0] / per_mm) * per_mm),
                       round(xy.get("Y", pos[1] / per_mm) * per_mm))
                if word[0] in ("G1", "G01"):
                    if cur is None:
                        cur = [prev]
                        strokes.append(cur)
                    cur.append(pos)
                prev = pos
    return strokes


def length(pts):
    return sum(math.hypot(b[0] - a[0], b[1] - a[1]) for a, b in zip(pts, pts[1:]))


def twice_steps(strokes):
    """Length drawn more than once by collinear overlapping segments: each segment filed by
    its exact line (primitive direction, offset), then per line the sum of the extents less
    their union."""
    lines = {}
    for pts in strokes:
        for (x0, y0), (x1, y1) in zip(pts, pts[1:]):
            a, b = x1 - x0, y1 - y0
            if a == 0 and b == 0:
                continue
            g = math.gcd(abs(a), abs(b))
            a, b = a // g, b // g
            if a < 0 or (a == 0 and b < 0):
                a, b = -a, -b
            t0, t1 = a * x0 + b * y0, a * x1 + b * y1
            lines.setdefault((a, b, b * x0 - a * y0), []).append((min(t0, t1), max(t0, t1)))
    total = 0.0
    for (a, b, _), spans in lines.items():
        if len(spans) < 2:
            continue
        spans.sort()
        extra, hi = 0, None
        for lo, h in spans:
            if hi is not None and lo < hi:
                extra += min(h, hi) - lo
            hi = h if hi is None or h > hi else hi
        total += extra / math.hypot(a, b)  # position is a*x + b*y: |(a, b)| per step
    return total


def measure(svg, gcode, per_mm):
    layers = svg_layers(svg, per_mm)
    s_strokes = [s for l in layers for s in l]
    g_strokes = gcode_strokes(gcode, per_mm)
    if len(s_strokes) != len(g_strokes):
        print("FAIL: %d strokes in the SVG, %d in the G-code" % (len(s_strokes), len(g_strokes)))
        sys.exit(1)
    crumb = CRUMB_MM * per_mm
    dots = max(sum(1 for s in ss if length(s) == 0) for ss in (s_strokes, g_strokes))
    crumbs = max(sum(1 for s in ss if length(s) < crumb) for ss in (s_strokes, g_strokes))
    twice = sum(twice_steps(l) for l in layers) / per_mm
    return len(s_strokes), dots, crumbs, twice


def main():
    what, svg, gcode, per_mm = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4])
    n, dots, crumbs, twice = measure(svg, gcode, per_mm)
    print("strokes=%d dots=%d crumbs=%d twice_mm=%.1f" % (n, dots, crumbs, twice))
    if what == "check":
        if dots > 0:
            print("FAIL: %d zero-length strokes" % dots)
        if crumbs * 100 > n:
            print("FAIL: %d of %d strokes under %.1f mm (over 1 %%)" % (crumbs, n, CRUMB_MM))
        if twice > 5:
            print("FAIL: %.1f mm drawn twice (over 5 mm)" % twice)
        if dots > 0 or crumbs * 100 > n or twice > 5:
            sys.exit(1)


if __name__ == "__main__":
    main()
