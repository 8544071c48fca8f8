#!/usr/bin/env python3
"""Reads a plot SVG, a G-code, an HPGL and a .spans file on its own (none of the tool's code)
and checks them against each other. Usage:
  svg_page_check.py page SVG W H MARGIN     page exactly W x H mm, no <rect>, every point
                                            inside the margins
  svg_page_check.py layers SVG LABEL...     one Inkscape layer per label, nothing else
  svg_page_check.py gcode SVG GCODE         the SVG's subpaths are the G-code's pen-down runs,
                                            in order, point for point (y = H - Y)
  svg_page_check.py segments SVG GCODE      the same pen-down segments, in any order
  svg_page_check.py hpgl SVG HPGL           the HPGL's PD runs are the subpaths (1/40 mm)
  svg_page_check.py pauses SVG GCODE HPGL N  the G-code stops (M0, pen up) exactly between
                                            layers and the HPGL selects each layer's pen by
                                            its number: the parts between them are the SVG's
                                            layers, in order (N: the layers expected); N = 0:
                                            no M0 at all, and the HPGL keeps pen 1
  svg_page_check.py extent SVG               prints the drawing's width in mm
  svg_page_check.py count SVG [LABEL]       prints the number of subpaths (of one layer)
  svg_page_check.py kinds SPANS             prints the kinds of line a .spans file holds
Exit 1 with a message on the first failure."""
import re
import sys
import xml.etree.ElementTree as ET

SVG_NS = "{http://www.w3.org/2000/svg}"
INK = "{http://www.inkscape.org/namespaces/inkscape}"


def fail(msg):
    print("FAILED: " + msg)
    sys.exit(1)


def thousandths(text):
    """'12.345' -> 12345 exactly (the files write three decimals)."""
    neg = text.startswith("-")
    whole, _, frac = text.lstrip("-").partition(".")
    v = int(whole or "0") * 1000 + int((frac + "000")[:3])
    if len(frac) > 3 and int(frac[3:]) != 0:
        fail("more than three decimals: " + text)
    return -v if neg else v


def subpaths(d):
    """A path's d as subpaths of absolute points (M, L and implicit lines; nothing else)."""
    out, cmd = [], None
    tokens = re.findall(r"[A-Za-z]|-?[0-9]*\.?[0-9]+", d)
    nums = []
    for t in tokens + ["END"]:
        if t.isalpha() or t == "END":
            if nums:
                if len(nums) % 2:
                    fail("odd number of coordinates in " + d[:80])
                pts = [(thousandths(nums[i]), thousandths(nums[i + 1])) for i in range(0, len(nums), 2)]
                if cmd == "M":
                    out.append(pts[:1])
                    out[-1].extend(pts[1:])
                elif cmd == "L":
                    if not out:
                        fail("L before M")
                    out[-1].extend(pts)
                else:
                    fail("unexpected path command " + str(cmd))
            nums = []
            cmd = t
        else:
            nums.append(t)
    return out


def load_svg(path):
    root = ET.parse(path).getroot()
    svg = {"root": root, "layers": [], "rects": 0, "all": []}
    for p in root.iter(SVG_NS + "path"):
        svg["all"].extend(subpaths(p.get("d")))
    for el in root.iter():
        if el.tag == SVG_NS + "rect":
            svg["rects"] += 1
    for g in root:
        if g.tag != SVG_NS + "g":
            continue
        strokes = []
        for p in g.iter(SVG_NS + "path"):
            strokes.extend(subpaths(p.get("d")))
        svg["layers"].append((g.get(INK + "groupmode"), g.get(INK + "label"), strokes))
    return svg


def all_strokes(svg, label=None):
    """Every subpath of the document in order, or those of one layer."""
    if label is None:
        return svg["all"]
    return [s for (_, l, strokes) in svg["layers"] if l == label for s in strokes]


def page_height(svg):
    return thousandths(svg["root"].get("height")[:-2])


def check_page(path, w, h, margin):
    svg = load_svg(path)
    root = svg["root"]
    if root.get("width") != w + "mm" or root.get("height") != h + "mm":
        fail("page %s x %s, want %smm x %smm" % (root.get("width"), root.get("height"), w, h))
    if [float(v) for v in root.get("viewBox").split()] != [0, 0, float(w), float(h)]:
        fail("viewBox " + root.get("viewBox") + " is not the page in mm")
    if svg["rects"]:
        fail("%d <rect> elements" % svg["rects"])
    lo, W, H, m = 0, thousandths(w), thousandths(h), thousandths(margin)
    n = 0
    for s in all_strokes(svg):
        for (x, y) in s:
            n += 1
            if not (m <= x <= W - m and m <= y <= H - m):
                fail("point (%.3f, %.3f) outside the %s mm margins" % (x / 1000, y / 1000, margin))
    if n == 0:
        fail("no points drawn")
    xs = [x for s in all_strokes(svg) for (x, _) in s]
    ys = [y for s in all_strokes(svg) for (_, y) in s]
    print("page ok: %d points, x %.3f..%.3f, y %.3f..%.3f" % (n, min(xs) / 1e3, max(xs) / 1e3, min(ys) / 1e3, max(ys) / 1e3))


def check_layers(path, labels):
    svg = load_svg(path)
    got = [l for (_, l, _) in svg["layers"]]
    if any(mode != "layer" for (mode, _, _) in svg["layers"]):
        fail("a top-level group is no inkscape layer")
    if sorted(got) != sorted(labels) or len(set(got)) != len(got):
        fail("layers %s, want %s" % (got, labels))
    for (_, l, strokes) in svg["layers"]:
        if not strokes:
            fail("layer %s is empty" % l)
    print("layers ok: " + ", ".join("%s (%d)" % (l, len(s)) for (_, l, s) in svg["layers"]))


def gcode_runs(path):
    """Pen-down runs: the point the pen went down at, then each G1 X Y while it is down."""
    return runs_of_lines(open(path))


def runs_of_lines(lines):
    runs, x, y, down = [], None, None, False
    for line in lines:
        f = line.split(";")[0].split()
        if not f:
            continue
        word = f[0]
        if word == "M5":
            down = False
        if word == "M3":
            down = True
            runs.append([(x, y)])
        args = {a[0]: a[1:] for a in f[1:]}
        if word == "G0" and "Z" in args:  # the Z pen lifted
            down = False
            continue
        if word == "G1" and "Z" in args:
            down = thousandths(args["Z"]) <= 0
            if down:
                runs.append([(x, y)])
            continue
        if word in ("G0", "G1") and "X" in args:
            x, y = thousandths(args["X"]), thousandths(args["Y"])
            if down:
                if word != "G1":
                    fail("G0 with the pen down")
                runs[-1].append((x, y))
    return [r for r in runs if len(r) > 1]


def flipped(svg, strokes):
    h = page_height(svg)
    return [[(x, h - y) for (x, y) in s] for s in strokes]


def check_gcode(path, gpath):
    svg = load_svg(path)
    mine, runs = flipped(svg, all_strokes(svg)), gcode_runs(gpath)
    if len(mine) != len(runs):
        fail("%d subpaths in the SVG, %d pen-down runs in the G-code" % (len(mine), len(runs)))
    for i, (a, b) in enumerate(zip(mine, runs)):
        if a != b:
            fail("stroke %d differs: SVG %s, G-code %s" % (i, a[:4], b[:4]))
    print("gcode ok: %d strokes, %d points, the same in order" % (len(runs), sum(len(r) for r in runs)))


def segments(strokes):
    out = []
    for s in strokes:
        for a, b in zip(s, s[1:]):
            out.append(tuple(sorted((a, b))))
    return sorted(out)


def check_segments(path, gpath):
    svg = load_svg(path)
    a, b = segments(flipped(svg, all_strokes(svg))), segments(gcode_runs(gpath))
    if a != b:
        only_a = set(a) - set(b)
        fail("%d SVG segments, %d G-code segments; e.g. only in the SVG: %s" % (len(a), len(b), list(only_a)[:2]))
    print("segments ok: %d pen-down segments, the same set" % len(a))


def check_hpgl(path, hpath):
    svg = load_svg(path)
    text = open(hpath).read().strip()
    runs, pos = [], None
    for cmd in text.split(";"):
        if cmd[:2] not in ("PU", "PD"):
            continue
        vals = [int(v) for v in cmd[2:].split(",") if v != ""]
        pts = list(zip(vals[0::2], vals[1::2]))
        if cmd[:2] == "PD" and pts:
            runs.append([pos] + pts)
        if pts:
            pos = pts[-1]
    mine = flipped(svg, all_strokes(svg))
    if len(mine) != len(runs):
        fail("%d subpaths, %d HPGL PD runs" % (len(mine), len(runs)))
    for s, r in zip(mine, runs):
        if len(s) != len(r):
            fail("a stroke of %d points against an HPGL run of %d" % (len(s), len(r)))
        for (x, y), (u, v) in zip(s, r):
            # 1/40 mm units from the same point: within a half unit and the SVG's rounding.
            if abs(u - x * 40 / 1000) > 0.501 or abs(v - y * 40 / 1000) > 0.501:
                fail("HPGL (%d, %d) is not the SVG's (%.3f, %.3f) mm" % (u, v, x / 1e3, y / 1e3))
    print("hpgl ok: %d runs" % len(runs))


def gcode_parts(gpath):
    """The G-code cut at each M0: a file per part (its lines), and whether the pen was down at
    each M0 (by the servo's M3/M5, or a Z at or below 0)."""
    parts, down_at, down = [[]], [], False
    for line in open(gpath):
        f = line.split(";")[0].split()
        if f and f[0] == "M0":
            down_at.append(down)
            parts.append([])
            continue
        parts[-1].append(line)
        if f and f[0] in ("M3", "M5"):
            down = f[0] == "M3"
        if f and f[0] == "G1" and any(a.startswith("Z") for a in f[1:]):
            down = thousandths([a for a in f[1:] if a.startswith("Z")][0][1:]) <= 0
        if f and f[0] == "G0" and any(a.startswith("Z") for a in f[1:]):
            down = False
    return parts, down_at


def hpgl_parts(hpath):
    """The HPGL cut at each SP: [(pen, runs)], runs as check_hpgl reads them."""
    parts, pos = [], None
    for cmd in open(hpath).read().strip().split(";"):
        if cmd.startswith("SP"):
            parts.append((int(cmd[2:]), []))
            continue
        if cmd[:2] not in ("PU", "PD"):
            continue
        vals = [int(v) for v in cmd[2:].split(",") if v != ""]
        pts = list(zip(vals[0::2], vals[1::2]))
        if cmd[:2] == "PD" and pts:
            parts[-1][1].append([pos] + pts)
        if pts:
            pos = pts[-1]
    return [(pen, runs) for (pen, runs) in parts if runs or pen != 0]


def near_hpgl(stroke, run):
    return len(stroke) == len(run) and all(
        abs(u - x * 40 / 1000) <= 0.501 and abs(v - y * 40 / 1000) <= 0.501
        for (x, y), (u, v) in zip(stroke, run))


def check_pauses(path, gpath, hpath, n):
    svg = load_svg(path)
    layers = [(l, flipped(svg, s)) for (_, l, s) in svg["layers"] if s]
    parts, down_at = gcode_parts(gpath)
    hparts = hpgl_parts(hpath)
    if n == 0:
        if len(parts) != 1:
            fail("%d M0 in a G-code that was not asked to pause" % (len(parts) - 1))
        if [pen for (pen, _) in hparts] != [1]:
            fail("HPGL pens %s, want only pen 1" % [pen for (pen, _) in hparts])
        print("no pauses ok: no M0, one HPGL pen")
        return
    if len(layers) != n:
        fail("%d layers in the SVG, want %d" % (len(layers), n))
    if len(parts) != n:
        fail("%d parts between M0s in the G-code, want %d (one per layer)" % (len(parts), n))
    if any(down_at):
        fail("an M0 with the pen down")
    for k, ((label, strokes), lines) in enumerate(zip(layers, parts)):
        runs = runs_of_lines(lines)
        if runs != strokes:
            fail("G-code part %d: %d pen-down runs, not layer %s's %d subpaths in order"
                 % (k + 1, len(runs), label, len(strokes)))
    pens = [pen for (pen, _) in hparts]
    numbers = [int(label.split()[0]) for (label, _) in layers]
    # The HPGL opens with SP1; a first layer of another number selects its pen at once.
    if pens != numbers and not (pens[0] == 1 and not hparts[0][1] and pens[1:] == numbers):
        fail("HPGL pens %s, want the layers' numbers %s" % (pens, numbers))
    hparts = [p for p in hparts if p[1]]
    for (label, strokes), (pen, runs) in zip(layers, hparts):
        if len(runs) != len(strokes) or not all(near_hpgl(s, r) for s, r in zip(strokes, runs)):
            fail("HPGL pen %d: its runs are not layer %s's subpaths" % (pen, label))
    print("pauses ok: %s, M0 and SPn exactly between them"
          % ", ".join("%s (%d)" % (l, len(s)) for (l, s) in layers))


def kinds(spath):
    found = set()
    for line in open(spath):
        f = line.split()
        if not f or f[0].startswith("#"):
            continue
        if f[0] == "o":
            found.add("outline")
        elif f[0] == "h":
            found.add("hatch")
        elif f[-1] == "0":
            found.add("visible")
        else:
            found.add("hidden")
    print(" ".join(sorted(found)))


def main(argv):
    cmd = argv[1]
    if cmd == "page":
        check_page(*argv[2:6])
    elif cmd == "layers":
        check_layers(argv[2], argv[3:])
    elif cmd == "gcode":
        check_gcode(argv[2], argv[3])
    elif cmd == "segments":
        check_segments(argv[2], argv[3])
    elif cmd == "hpgl":
        check_hpgl(argv[2], argv[3])
    elif cmd == "extent":
        xs = [x for s in all_strokes(load_svg(argv[2])) for (x, _) in s]
        print("%.3f" % ((max(xs) - min(xs)) / 1000))
    elif cmd == "count":
        print(len(all_strokes(load_svg(argv[2]), argv[3] if len(argv) > 3 else None)))
    elif cmd == "pauses":
        check_pauses(argv[2], argv[3], argv[4], int(argv[5]))
    elif cmd == "kinds":
        kinds(argv[2])
    else:
        fail("unknown check " + cmd)


if __name__ == "__main__":
    main(sys.argv)
