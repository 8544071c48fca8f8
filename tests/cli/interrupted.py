#!/usr/bin/env python3
"""A plot stopped by SIGTERM or SIGINT while it writes leaves nothing half-written: no PATH.tmp
beside an output, no staged copy in TMPDIR, and the process ends by that signal.

The plot writes its SVG to a FIFO nobody reads and its G-code to a file: the outputs are
staged, then committed in order, and the commit waits on the FIFO, so the signal arrives at a
known point with the staged files on disk (the test waits for them, not for a clock).

  interrupted.py TOOL MODEL WORKDIR
"""
import glob
import os
import shutil
import signal
import subprocess
import sys
import time


def run(tool, model, work, sig):
    if os.path.isdir(work):
        shutil.rmtree(work)
    tmp = os.path.join(work, "tmp")
    os.makedirs(tmp)
    fifo = os.path.join(work, "page.svg")
    os.mkfifo(fifo)
    gcode = os.path.join(work, "page.gcode")
    env = dict(os.environ, TMPDIR=tmp)
    p = subprocess.Popen([tool, "plot", model, "--mode", "hidden-removed", "-o", fifo,
                          "--gcode", gcode], env=env, stderr=subprocess.PIPE)
    # Wait for the staged SVG (in TMPDIR: a FIFO is written through on commit) while the
    # process runs; each look is a tenth of a second, and the plot ends only through the FIFO.
    while not glob.glob(os.path.join(tmp, "haloplot-out-*")):
        if p.poll() is not None:
            sys.exit("FAIL: the plot ended before staging: %s" % p.stderr.read().decode())
        time.sleep(0.1)
    time.sleep(0.2)  # let it reach the FIFO's open, where it waits
    staged = sorted(glob.glob(os.path.join(tmp, "*")) + glob.glob(os.path.join(work, "*.tmp")))
    p.send_signal(sig)
    rc = p.wait()
    left = sorted(glob.glob(os.path.join(tmp, "*")) + glob.glob(os.path.join(work, "*.tmp")))
    name = signal.Signals(sig).name
    bad = []
    if rc != -sig:
        bad.append("ended with %d, not by %s" % (rc, name))
    if left:
        bad.append("left behind: %s" % ", ".join(left))
    if os.path.exists(gcode) and os.path.getsize(gcode) == 0:
        bad.append("an empty G-code")
    if bad:
        sys.exit("FAIL (%s): %s" % (name, "; ".join(bad)))
    print("%s: staged %d file(s) when signalled, none left" % (name, len(staged)))


def main():
    tool, model, work = sys.argv[1], sys.argv[2], sys.argv[3]
    for sig in (signal.SIGTERM, signal.SIGINT):
        run(tool, model, os.path.join(work, signal.Signals(sig).name), sig)


if __name__ == "__main__":
    main()
