#!/usr/bin/env python3
"""Models for plot_defaults.sh, and an SVG ink comparison written apart from haloplot's code.

  box-stl OUT.stl        a 3 x 2 x 1.5 box, each face a 4 x 4 grid of squares split into
                         triangles (192), turned by 0.7 rad about (1, 2, 3) and moved off the
                         origin, as a float32 binary STL (every coordinate rounded to float32:
                         the grid's corners are no longer exactly coplanar)
  box-obj OUT.obj        the same box as its 8 corners and 6 quads, printed to 9 decimals
  soup SOUP.obj TWIN.obj a torus (24 x 12 quads, each split into 2 triangles) as a triangle
                         soup, every triangle its own 3 corners, every other copy of a corner
                         moved by 6 units in the 6th decimal in x, y and z (0.75 world units:
                         under the default weld distance, about 1.9, and mostly to another
                         world position, so --weld 0 does not join them), and its welded twin: the same triangles on
                         shared corners, numbered as the soup first names them
  compare A.svg B.svg TOL  the strokes of both pictures: total ink (mm) within 0.5 %, and every
                         point of every segment of each within TOL mm of the other's segments.
                         Exit 0 if the same, 1 if not (the reason on stdout), 2 if a picture
                         cannot be read.
"""
import math
import re
import struct
import sys


def rotate(p, axis=(1.0, 2.0, 3.0), angle=0.7):
    """Rodrigues' rotation of p about the unit axis, then moved off the origin."""
    n = math.sqrt(sum(a * a for a in axis))
    k = [a / n for a in axis]
    c, s = math.cos(angle), math.sin(angle)
    dot = sum(k[i] * p[i] for i in range(3))
    cross = (k[1] * p[2] - k[2] * p[1], k[2] * p[0] - k[0] * p[2], k[0] * p[1] - k[1] * p[0])
    offset = (10.0, 20.0, 5.0)
    return tuple(p[i] * c + cross[i] * s + k[i] * dot * (1 - c) + offset[i] for i in range(3))


SIZE = (3.0, 2.0, 1.5)
GRID = 4


def lattice(i, j, k):
    """The box point at grid indices (0..GRID each), turned: shared corners get equal doubles."""
    return rotate(tuple((q / GRID - 0.5) * SIZE[a] for a, q in enumerate((i, j, k))))


def box_faces():
    """Each face's grid squares as 4 lattice indices, counterclockwise seen from outside."""
    for axis in range(3):
        u, v = (axis + 1) % 3, (axis + 2) % 3
        for side in (0, GRID):
            for a in range(GRID):
                for b in range(GRID):
                    quad = []
                    for du, dv in ((0, 0), (1, 0), (1, 1), (0, 1)):
                        idx = [0, 0, 0]
                        idx[axis], idx[u], idx[v] = side, a + du, b + dv
                        quad.append(tuple(idx))
                    yield quad if side == GRID else quad[::-1]


def box_stl(path):
    tris = []
    for q in box_faces():
        tris += [(q[0], q[1], q[2]), (q[0], q[2], q[3])]
    with open(path, "wb") as f:
        f.write(b"binary STL of a turned grid box".ljust(80, b" "))
        f.write(struct.pack("<I", len(tris)))
        for t in tris:
            f.write(struct.pack("<3f", 0, 0, 0))
            for idx in t:
                f.write(struct.pack("<3f", *lattice(*idx)))
            f.write(struct.pack("<H", 0))


def box_obj(path):
    corners = [(i, j, k) for i in (0, GRID) for j in (0, GRID) for k in (0, GRID)]
    with open(path, "w") as f:
        for c in corners:
            f.write("v %.9f %.9f %.9f\n" % lattice(*c))
        for axis in range(3):
            u, v = (axis + 1) % 3, (axis + 2) % 3
            for side in (0, GRID):
                quad = []
                for du, dv in ((0, 0), (GRID, 0), (GRID, GRID), (0, GRID)):
                    idx = [0, 0, 0]
                    idx[axis], idx[u], idx[v] = side, du, dv
                    quad.append(corners.index(tuple(idx)) + 1)
                quad = quad if side == GRID else quad[::-1]
                f.write("f %d %d %d %d\n" % tuple(quad))


def soup(soup_path, twin_path):
    nu, nv, big, small = 24, 12, 1.5, 0.6

    def at(i, j):
        u, v = 2 * math.pi * (i % nu) / nu, 2 * math.pi * (j % nv) / nv
        return ((big + small * math.cos(v)) * math.cos(u), small * math.sin(v),
                (big + small * math.cos(v)) * math.sin(u))

    tris = []
    for i in range(nu):
        for j in range(nv):
            a, b, c, d = (i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)
            tris += [(a, d, c), (a, c, b)]
    key = lambda p: (p[0] % nu, p[1] % nv)
    jitter = [0.0, 6e-6]
    with open(soup_path, "w") as f:
        n = 0
        for t in tris:
            for p in t:
                x, y, z = at(*p)
                e = jitter[n % 2]
                f.write("v %.6f %.6f %.6f\n" % (x + e, y + e, z - e))
                n += 1
        for k in range(len(tris)):
            f.write("f %d %d %d\n" % (3 * k + 1, 3 * k + 2, 3 * k + 3))
    order = {}
    for t in tris:
        for p in t:
            order.setdefault(key(p), len(order) + 1)
    with open(twin_path, "w") as f:
        for p in sorted(order, key=order.get):
            f.write("v %.6f %.6f %.6f\n" % at(*p))
        for t in tris:
            f.write("f %d %d %d\n" % tuple(order[key(p)] for p in t))


def segments(path):
    """Every straight piece of every path's subpaths ("M x,y L x,y x,y ..."), in mm."""
    out = []
    for d in re.findall(r' d="([^"]*)"', open(path).read()):
        for sub in d.split("M")[1:]:
            pts = [tuple(float(c) for c in w.split(",")) for w in sub.replace("L", " ").split()]
            out += [(p, q) for p, q in zip(pts, pts[1:])]
    return out


def point_segment(p, a, b):
    dx, dy = b[0] - a[0], b[1] - a[1]
    L2 = dx * dx + dy * dy
    t = 0.0 if L2 == 0 else max(0.0, min(1.0, ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / L2))
    return math.hypot(p[0] - a[0] - t * dx, p[1] - a[1] - t * dy)


def far_points(a_segs, b_segs, tol, cell=2.0):
    """Points sampled along a's segments (every 0.25 mm) farther than tol from all of b's."""
    grid = {}
    for s in b_segs:
        x0, x1 = sorted((s[0][0], s[1][0]))
        y0, y1 = sorted((s[0][1], s[1][1]))
        for gx in range(int((x0 - tol) // cell), int((x1 + tol) // cell) + 1):
            for gy in range(int((y0 - tol) // cell), int((y1 + tol) // cell) + 1):
                grid.setdefault((gx, gy), []).append(s)
    far = []
    for a, b in a_segs:
        n = max(1, int(math.dist(a, b) / 0.25))
        for k in range(n + 1):
            p = (a[0] + (b[0] - a[0]) * k / n, a[1] + (b[1] - a[1]) * k / n)
            near = grid.get((int(p[0] // cell), int(p[1] // cell)), [])
            if not any(point_segment(p, *s) <= tol for s in near):
                far.append(p)
    return far


def compare(a_path, b_path, tol):
    a, b = segments(a_path), segments(b_path)
    ink_a = sum(math.dist(*s) for s in a)
    ink_b = sum(math.dist(*s) for s in b)
    far_a, far_b = far_points(a, b, tol), far_points(b, a, tol)
    print("ink %.1f mm and %.1f mm; %d and %d points farther than %g mm from the other's" %
          (ink_a, ink_b, len(far_a), len(far_b), tol))
    same = ink_a > 0 and abs(ink_a - ink_b) <= 0.005 * max(ink_a, ink_b) and not far_a and not far_b
    return 0 if same else 1


if __name__ == "__main__":
    what = sys.argv[1]
    if what == "box-stl":
        box_stl(sys.argv[2])
    elif what == "box-obj":
        box_obj(sys.argv[2])
    elif what == "soup":
        soup(sys.argv[2], sys.argv[3])
    elif what == "compare":
        try:
            result = compare(sys.argv[2], sys.argv[3], float(sys.argv[4]))
        except (OSError, ValueError) as e:  # no picture to compare is neither same nor different
            print("cannot compare: %s" % e)
            result = 2
        sys.exit(result)
    else:
        sys.exit("unknown command " + what)
