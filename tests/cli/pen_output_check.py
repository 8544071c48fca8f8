#!/usr/bin/env python3
"""Independent readers for tests/cli/pen_output.sh: an SVG's layers, a G-code's dwells and
pen moves, and the plot summary on stderr. Reads the files only (xml.etree, plain text), none
of the tool's code.

  pen_output_check.py layers SVG          each layer's id number is its label's, colours distinct
  pen_output_check.py pens SVG HPGL       the HPGL selects each layer's pen by its SVG id number
  pen_output_check.py dwells GRBL MARLIN  every Marlin dwell is G4 P<integer ms>, 1000 x grbl's
  pen_output_check.py around GCODE HEADER FOOTER
                                          the header's lines right after G90, the footer's
                                          right before the end (after the last pen-up)
  pen_output_check.py summary GCODE STDERR
                                          the summary's strokes and pen-up travel are the
                                          G-code's pen-downs and G0 travel from (0, 0) home
"""
import math
import re
import sys
import xml.etree.ElementTree as ET

SVG = "{http://www.w3.org/2000/svg}"
INK = "{http://www.inkscape.org/namespaces/inkscape}"


def fail(msg):
    print("FAIL: " + msg)
    sys.exit(1)


def check_layers(path):
    root = ET.parse(path).getroot()
    layers = [g for g in root if g.tag == SVG + "g" and g.get(INK + "groupmode") == "layer"]
    if not layers:
        fail("no Inkscape layer in " + path)
    colours = {}
    for g in layers:
        label, ident = g.get(INK + "label") or "", g.get("id") or ""
        m = re.fullmatch(r"layer(\d+)", ident)
        n = re.match(r"(\d+) ", label)
        if not m or not n:
            fail("layer id %r / label %r: want id layerN and a label starting with N" % (ident, label))
        if int(m.group(1)) != int(n.group(1)):
            fail("layer id %s carries label %r: the numbers differ" % (ident, label))
    for g in layers:  # the ids first, so each fault is told on its own
        label = g.get(INK + "label")
        stroke = (g.get("stroke") or "").lower()
        for p in g.iter(SVG + "path"):  # a path's own stroke would override the layer's
            if p.get("stroke") is not None:
                stroke = p.get("stroke").lower()
        if stroke in colours.values():
            fail("layer %r has the stroke %s of another layer: %s" % (label, stroke, colours))
        colours[label] = stroke
    print("layers ok: " + ", ".join("%s=%s" % kv for kv in colours.items()))


def check_pens(svg, hpgl):
    root = ET.parse(svg).getroot()
    ids = [int(re.fullmatch(r"layer(\d+)", g.get("id")).group(1)) for g in root
           if g.tag == SVG + "g" and g.get(INK + "groupmode") == "layer"]
    with open(hpgl) as f:
        pens = [int(n) for n in re.findall(r"SP(\d+);", f.read())]
    pens = [n for n in pens if n != 0]  # SP0: the pen put away at the end
    if pens[:1] == [1] and ids[:1] != [1]:
        pens = pens[1:]  # IN;SP1; opens every file
    if pens != ids:
        fail("HPGL pens %s, the SVG's layer ids %s" % (pens, ids))
    print("pens ok: " + " ".join("SP%d" % n for n in pens))


def lines(path):
    with open(path) as f:
        return [l.strip() for l in f]


def check_dwells(grbl, marlin):
    g = [l for l in lines(grbl) if l.startswith("G4")]
    m = [l for l in lines(marlin) if l.startswith("G4")]
    if not g or len(g) != len(m):
        fail("%d dwells in the grbl file, %d in the marlin file" % (len(g), len(m)))
    for a, b in zip(g, m):
        seconds = re.fullmatch(r"G4 P(\d+(?:\.\d+)?)", a)
        ms = re.fullmatch(r"G4 P(\d+)", b)
        if not seconds or not ms:
            fail("dwell %r / %r: want G4 P<seconds> / G4 P<integer ms>" % (a, b))
        if round(float(seconds.group(1)) * 1000) != int(ms.group(1)):
            fail("marlin dwell %s ms is not 1000 x grbl's %s s" % (ms.group(1), seconds.group(1)))
    print("dwells ok: %d, P%s ms" % (len(m), ms.group(1)))


def check_around(path, header, footer):
    ls = [l for l in lines(path) if l]
    want_h = header.split("\\n")
    want_f = footer.split("\\n")
    at = ls.index("G90") + 1 if "G90" in ls else -1
    if at < 0 or ls[at:at + len(want_h)] != want_h:
        fail("header %s not right after G90: %s" % (want_h, ls[:8]))
    # The footer ends the file, or precedes the dialect's last line (M2 in grbl).
    tail = ls[-len(want_f):] if ls[-len(want_f):] == want_f else ls[-len(want_f) - 1:-1]
    if tail != want_f:
        fail("footer %s not at the end: %s" % (want_f, ls[-6:]))
    # ...and after the last move.
    last_move = max(i for i, l in enumerate(ls) if re.match(r"G[01] ", l))
    if ls.index(want_f[0], last_move) < last_move:
        fail("footer before the last move")
    print("header and footer ok")


PEN_DOWN = re.compile(r"^(M3\b|M280 P0 S(\d+)|G1 Z)")


def gcode_figures(path):
    """Pen-downs written and the pen-up travel (mm) of the moves made with the pen up, from
    (0, 0), the machine's origin where the plot begins."""
    x = y = 0.0
    down = False
    downs = 0
    travel = 0.0
    up_angle = None
    for l in lines(path):
        l = l.split(";")[0].strip()
        if not l:
            continue
        if l.startswith("M3") or l.startswith("G1 Z"):
            down = True
            downs += 1
        elif l.startswith("M5") or l.startswith("G0 Z"):
            down = False
        elif l.startswith("M280"):
            raise SystemExit("summary check reads grbl files only")
        elif re.match(r"G[01] X", l):
            w = dict((k, float(v)) for k, v in re.findall(r"([XY])(-?\d+(?:\.\d+)?)", l))
            nx, ny = w.get("X", x), w.get("Y", y)
            if not down:
                travel += math.hypot(nx - x, ny - y)
            x, y = nx, ny
    return downs, travel


def check_summary(gcode, stderr):
    with open(stderr) as f:
        text = f.read()
    m = re.search(r"(\d+) strokes?, pen down ([\d.]+) mm, pen up ([\d.]+) mm", text)
    if not m:
        fail("no summary in stderr: " + text[-300:])
    strokes, up = int(m.group(1)), float(m.group(3))
    downs, travel = gcode_figures(gcode)
    bad = []
    if abs(strokes - downs) > 0.005 * downs:
        bad.append("strokes %d, the G-code's pen-downs %d" % (strokes, downs))
    if abs(up - travel) > 0.005 * travel:
        bad.append("pen up %.3f mm, the G-code's pen-up travel %.3f mm" % (up, travel))
    if bad:
        fail("; ".join(bad))
    print("summary ok: %d strokes, pen up %.3f mm (G-code %d, %.3f mm)" % (strokes, up, downs, travel))


def main(argv):
    cmd = argv[1]
    if cmd == "layers":
        check_layers(argv[2])
    elif cmd == "pens":
        check_pens(argv[2], argv[3])
    elif cmd == "dwells":
        check_dwells(argv[2], argv[3])
    elif cmd == "around":
        check_around(argv[2], argv[3], argv[4])
    elif cmd == "summary":
        check_summary(argv[2], argv[3])
    else:
        fail("unknown check " + cmd)


if __name__ == "__main__":
    main(sys.argv)
