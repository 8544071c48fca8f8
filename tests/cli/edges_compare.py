#!/usr/bin/env python3
"""Compares two projected scenes (.edges dumps, edge by edge in the model's order) within a
tolerance, after an optional turn of the first about the view axis. Written from the
convention docs/cli.md states, not from the tool's code:

  same A B TOL                 every endpoint of A equals B's within TOL (x, y; units of the
                               dump), and both have the same number of edges
  roll A B DEG TOL_STEPS       A turned DEG counterclockwise, then both normalised to their
                               bounding box (translated to 0, divided by the larger side, as
                               a uniform fit does): every endpoint agrees within TOL_STEPS
                               steps of B's fit
  depth_d OBJ UP FOV           the perspective distance a --fov camera looking at the model's
                               bounding-box centre must get (printed with that centre): world = the file centred on its
                               bounding box, scaled so its largest extent is 2^19, rounded,
                               turned Z-up; R = the farthest vertex; ceil(R / sin(FOV / 2))

Exit status: 0 agree, 1 differ, 3 a file missing or malformed.
"""
import math
import sys


def read_edges(path):
    substep, edges = 0, []
    for line in open(path):
        if line.startswith("# substep"):
            substep = int(line.split()[2])
        if line.startswith("#") or not line.strip():
            continue
        v = [int(t) for t in line.split()]
        edges.append(((v[0], v[1]), (v[3], v[4])))
    return substep, edges


def normalised(edges):
    xs = [p[0] for e in edges for p in e]
    ys = [p[1] for e in edges for p in e]
    x0, y0 = min(xs), min(ys)
    side = max(max(xs) - x0, max(ys) - y0)
    return [tuple(((p[0] - x0) / side, (p[1] - y0) / side) for p in e) for e in edges], side


def worst(a, b):
    return max(max(abs(p[0] - q[0]), abs(p[1] - q[1])) for ea, eb in zip(a, b)
               for p, q in zip(ea, eb))


def main():
    cmd = sys.argv[1]
    if cmd == "same":
        _, a = read_edges(sys.argv[2])
        _, b = read_edges(sys.argv[3])
        tol = float(sys.argv[4])
        if len(a) != len(b):
            sys.exit(f"{len(a)} edges against {len(b)}")
        w = worst(a, b)
        print(f"{len(a)} edges, largest difference {w} (tolerance {tol})")
        sys.exit(0 if w <= tol else 1)
    if cmd == "roll":
        sub, a = read_edges(sys.argv[2])
        _, b = read_edges(sys.argv[3])
        r = math.radians(float(sys.argv[4]))
        c, s = math.cos(r), math.sin(r)
        turned = [tuple((p[0] * c - p[1] * s, p[0] * s + p[1] * c) for p in e) for e in a]
        na, _ = normalised(turned)
        nb, side = normalised(b)
        if len(na) != len(nb):
            sys.exit(f"{len(na)} edges against {len(nb)}")
        w = worst(na, nb) * side / (1 << sub)  # in steps of B's fit
        tol = float(sys.argv[5])
        print(f"{len(na)} edges, largest difference {w:.4f} steps (tolerance {tol})")
        sys.exit(0 if w <= tol else 1)
    if cmd == "depth_d":
        xyz = [[float(t) for t in l.split()[1:4]] for l in open(sys.argv[2]) if l.startswith("v ")]
        lo = [min(p[a] for p in xyz) for a in range(3)]
        hi = [max(p[a] for p in xyz) for a in range(3)]
        scale = 2**19 / max(hi[a] - lo[a] for a in range(3))
        # lround: halves away from zero
        rnd = lambda v: int(math.floor(abs(v) + 0.5)) * (1 if v >= 0 else -1)
        r2 = max(sum(rnd((p[a] - (lo[a] + hi[a]) / 2) * scale) ** 2 for a in range(3))
                 for p in xyz)  # a turn of the axes keeps the distance
        d = math.ceil(math.sqrt(r2) / math.sin(math.radians(float(sys.argv[4]) / 2)))
        print(d, ",".join(repr((lo[a] + hi[a]) / 2) for a in range(3)))
        return
    sys.exit("unknown command " + cmd)


try:
    main()
except (OSError, ValueError, IndexError, ZeroDivisionError) as e:
    print("error:", e)
    sys.exit(3)  # not a difference: a missing or malformed file
