#!/usr/bin/env python3
"""Compares the pen-down segments of two G-code files, read here on their own.

Usage: gcode_pen_down.py A.gcode B.gcode [STEPS_PER_MM]

A segment is one G1 move made with the pen down (after M3, before M5), from where the pen was
to the move's X Y, in plot steps (mm times STEPS_PER_MM, 80 unless given). Segments are
undirected: a band may draw a chord the other way round. Every segment of A must match one of B
(each used once) with both ends within one step, and B must have none left over. Prints the
counts and the largest end difference in steps; exit status 0 when they match, 1 when they
do not, 2 when a file cannot be read.
"""
import math
import re
import sys

MOVE = re.compile(r"^G([01])\b(.*)$")
WORD = re.compile(r"([XYZF])(-?[0-9.]+)")


def segments(path, per_mm):
    pen = False
    x = y = None
    out = []
    with open(path) as f:
        for line in f:
            line = line.split(";")[0].strip()
            if not line:
                continue
            if line.startswith("M3"):
                pen = True
                continue
            if line.startswith("M5"):
                pen = False
                continue
            m = MOVE.match(line)
            if not m:
                continue
            words = dict(WORD.findall(m.group(2)))
            nx = float(words["X"]) * per_mm if "X" in words else x
            ny = float(words["Y"]) * per_mm if "Y" in words else y
            if pen and m.group(1) == "1" and x is not None and (nx, ny) != (x, y):
                out.append(((x, y), (nx, ny)))
            x, y = nx, ny
    return out


def end_gap(s, t):
    """The larger end distance (steps) of s and t, the better way round."""
    def d(p, q):
        return math.hypot(p[0] - q[0], p[1] - q[1])
    same = max(d(s[0], t[0]), d(s[1], t[1]))
    other = max(d(s[0], t[1]), d(s[1], t[0]))
    return min(same, other)


def main():
    if len(sys.argv) < 3:
        print(__doc__)
        return 2
    per_mm = float(sys.argv[3]) if len(sys.argv) > 3 else 80.0
    try:
        a = segments(sys.argv[1], per_mm)
        b = segments(sys.argv[2], per_mm)
    except (OSError, ValueError, KeyError) as e:
        print("cannot read: %s" % e)
        return 2
    # Candidates by the rounded midpoint's cell: a match within a step lies in a neighbouring
    # cell of 4 steps.
    cells = {}
    for i, s in enumerate(b):
        key = (round((s[0][0] + s[1][0]) / 8), round((s[0][1] + s[1][1]) / 8))
        cells.setdefault(key, []).append(i)
    used = [False] * len(b)
    worst = 0.0
    unmatched = 0
    for s in a:
        cx, cy = round((s[0][0] + s[1][0]) / 8), round((s[0][1] + s[1][1]) / 8)
        best, best_gap = None, None
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                for i in cells.get((cx + dx, cy + dy), []):
                    if used[i]:
                        continue
                    g = end_gap(s, b[i])
                    if best_gap is None or g < best_gap:
                        best, best_gap = i, g
        if best is None or best_gap > 1.0 + 1e-9:
            unmatched += 1
            continue
        used[best] = True
        worst = max(worst, best_gap)
    left = used.count(False)
    length = lambda segs: sum(math.hypot(q[0] - p[0], q[1] - p[1]) for p, q in segs)
    print("segments %d and %d, %d matched, %d of the first and %d of the second unmatched, "
          "largest end difference %.3f steps, pen down %.1f and %.1f steps"
          % (len(a), len(b), len(a) - unmatched, unmatched, left, worst, length(a), length(b)))
    return 0 if unmatched == 0 and left == 0 and len(a) > 0 else 1


if __name__ == "__main__":
    sys.exit(main())
