#!/usr/bin/env python3
"""The include rules, with one include parser for both.

  includes.py SOURCE_DIR layers       layers point one way (below)
  includes.py SOURCE_DIR paths        every include names a file at that path in the tree, and
                                      no CMake file links or copies headers at configure time
  includes.py SOURCE_DIR MODE plant KIND|all
                                      copies the tree, plants one violation of KIND (of each
                                      kind, one at a time) and passes only if the rule then fails
                                      on the planted file and nothing else: a checker shown to
                                      catch what it guards (`plant list` names the kinds)

Every form of include is read: "..." and <...>, spaces after '#', paths with '//', './' or
'../', any C or C++ file suffix. An include is resolved as the compiler would: beside the
including file first (quoted form), then the tree's include roots; what resolves to no file
in the tree is a system or toolchain header and is not the rules' business.

Layers, from the bottom. core/ and hal/: status geometry sort hal < memory < scene view view2d
< cut < draw < curve solid < surface < motion < trace < band < job < protocol < controller;
a file includes its own folder or one of a lower rank (folders of one rank do not include
each other), and nothing outside core/ and hal/. host_sim/: io demo < pipeline < export link
< render sim < cli; it may include the core, never firmware/ or tests/. firmware/ includes
nothing from tests/ or host_sim/, and its CMake puts no tests/ folder on an include path.
"""
import os
import posixpath
import re
import shutil
import sys
import tempfile

CORE_RANK = {
    "status": 0, "geometry": 0, "sort": 0, "hal": 0, "memory": 1, "scene": 2, "view": 2,
    "view2d": 2, "cut": 3, "draw": 4, "curve": 5, "solid": 5, "surface": 6, "motion": 7,
    "trace": 8, "band": 9, "job": 10, "protocol": 11, "controller": 12, "haloplot.h": 13,
}
HOST_RANK = {"io": 0, "demo": 0, "pipeline": 1, "export": 2, "link": 2, "render": 3, "sim": 3,
             "cli": 4}
SOURCE = re.compile(r"\.(h|hh|hpp|hxx|c|cc|cpp|cxx|inc|ipp)$", re.I)
INCLUDE = re.compile(r'^\s*#\s*include\s*([<"])([^>"]+)[>"]')
PARTS = ["core", "hal", "firmware", "host_sim", "tests", "examples"]


def sources(src):
    for part in PARTS:
        for root, dirs, files in os.walk(os.path.join(src, part)):
            dirs[:] = [d for d in dirs if d != "build"]
            for f in sorted(files):
                if SOURCE.search(f):
                    yield os.path.relpath(os.path.join(root, f), src)


def includes(src, rel):
    with open(os.path.join(src, rel), encoding="utf-8", errors="replace") as f:
        for n, line in enumerate(f, 1):
            m = INCLUDE.match(line)
            if m:
                yield n, m.group(1), m.group(2)


def roots(src):
    r = ["core/include", "hal/include", "core", "host_sim", "firmware", "tests"]
    boards = os.path.join(src, "firmware/boards")
    if os.path.isdir(boards):
        r += ["firmware/boards/" + b for b in sorted(os.listdir(boards))]
    return r


def resolve(src, rel, quote, text):
    """The tree path the include reaches, or None (a system or toolchain header)."""
    tries = []
    if quote == '"':
        tries.append(posixpath.join(posixpath.dirname(rel), text))
    tries += [posixpath.join(r, text) for r in roots(src)]
    for t in tries:
        t = posixpath.normpath(t)
        if not t.startswith("..") and os.path.isfile(os.path.join(src, t)):
            return t
    return None


def place(path):
    """(part, folder) of a tree path: ('core', stage), ('host', folder), ('firmware', ''), ..."""
    p = path.split("/")
    if p[0] == "hal":
        return "core", "hal"
    if p[0] == "core":
        if p[1] == "include":
            return "core", p[3] if len(p) > 4 else p[3]  # haloplot/<stage>/x.h or haloplot/x.h
        return "core", p[1] if len(p) > 2 else ""
    if p[0] == "host_sim":
        return "host", p[1] if len(p) > 2 else ""
    return p[0], ""


def layer_violation(rel, target):
    part, folder = place(rel)
    tpart, tfolder = place(target)
    if part == "core":
        if tpart != "core":
            return "includes %s, outside the core" % target
        own, their = CORE_RANK.get(folder), CORE_RANK.get(tfolder)
        if folder == tfolder:
            return None
        if own is None or their is None or their >= own:
            return "includes %s/, not a layer below %s/" % (tfolder, folder)
    elif part == "host":
        if tpart in ("tests", "firmware"):
            return "includes %s, outside the host tool" % target
        if tpart == "host" and tfolder != folder:
            own, their = HOST_RANK.get(folder), HOST_RANK.get(tfolder)
            if own is None or their is None or their >= own:
                return "includes %s/, not a layer below %s/" % (tfolder, folder)
    elif part == "firmware":
        if tpart in ("tests", "host"):
            return "includes %s, which the firmware may not" % target
    return None


def cmake_files(src):
    for root, dirs, files in os.walk(src):
        dirs[:] = [d for d in dirs if d not in ("build", ".git")]
        for f in files:
            if f == "CMakeLists.txt" or f.endswith(".cmake"):
                yield os.path.relpath(os.path.join(root, f), src)


def cmake_commands(src, rel):
    """(command, its argument text) for every call in a CMake file, across lines."""
    text = open(os.path.join(src, rel), encoding="utf-8").read()
    text = re.sub(r"#[^\n]*", "", text)
    for m in re.finditer(r"\b(\w+)\s*\(", text):
        depth, i = 1, m.end()
        while i < len(text) and depth:
            depth += {"(": 1, ")": -1}.get(text[i], 0)
            i += 1
        yield m.group(1).lower(), text[m.end():i - 1]


def check_layers(src):
    bad, n = [], 0
    for rel in sources(src):
        for line, quote, text in includes(src, rel):
            target = resolve(src, rel, quote, text)
            if target is None:
                continue
            n += 1
            why = layer_violation(rel, target)
            if why:
                bad.append("%s:%d: %s" % (rel, line, why))
    for rel in cmake_files(src):
        if not rel.startswith("firmware/"):
            continue
        for cmd, args in cmake_commands(src, rel):
            if "include_directories" in cmd and re.search(r"\btests\b", args):
                bad.append("%s: puts a tests/ folder on the firmware's include path" % rel)
    return n, bad


def check_paths(src):
    bad, n = [], 0
    stages = set(os.listdir(os.path.join(src, "core"))) - {"include", "CMakeLists.txt"}
    for rel in sources(src):
        for line, quote, text in includes(src, rel):
            first = text.split("/")[0]
            if first == "haloplot":
                n += 1
                if posixpath.normpath(text) != text:
                    bad.append("%s:%d: %s is not written as its path" % (rel, line, text))
                elif not any(os.path.isfile(os.path.join(src, r, text))
                             for r in ("core/include", "hal/include")):
                    bad.append("%s:%d: %s is not under core/include or hal/include"
                               % (rel, line, text))
            elif "/" in text and first in stages and place(rel)[0] in ("core", "tests"):
                n += 1
                if not os.path.isfile(os.path.join(src, "core", text)):
                    bad.append("%s:%d: %s is not under core/" % (rel, line, text))
    for rel in cmake_files(src):
        for cmd, args in cmake_commands(src, rel):
            made = (cmd == "file" and re.match(r"\s*(COPY|CREATE_LINK|COPY_FILE)\b", args)) or \
                   re.search(r"create_symlink|copy_if_different|copy_directory|\bln\s+-s", args) or \
                   (cmd == "configure_file" and re.search(r"\.(h|hpp)\b", args))
            if made:
                bad.append("%s: %s(%s...) makes links or copies at configure time"
                           % (rel, cmd, args.strip()[:40]))
    return n, bad


# What `plant` adds: (file, line to insert at the top); every one must make the rule fail.
PLANTS = {
    "layers": {
        "core": ("core/cut/grid.cpp", "#include <haloplot/job/job.h>"),
        "core_relative": ("core/cut/grid.cpp", '#include "../band/band_attempt.h"'),
        "core_slashes": ("core/cut/grid.cpp", '#include "haloplot//job/job.h"'),
        "hal": ("hal/include/haloplot/hal/pen.h", '#include "haloplot/job/job.h"'),
        "host_cli": ("host_sim/pipeline/triangulate.cpp", '#include "../cli/options.h"'),
        "host_io": ("host_sim/io/edges_file.cpp", '#  include <pipeline/host_pipeline.h>'),
        "firmware": ("firmware/selftest/hello.cpp", '#include "../../tests/check.h"'),
        "firmware_cmake": ("firmware/CMakeLists.txt",
                           "target_include_directories(haloplot_fw_platform PRIVATE\n"
                           "  ${PROJECT_SOURCE_DIR}/tests)"),
    },
    "paths": {
        "missing": ("core/cut/grid.cpp", '#include "haloplot/cut/cut_grid.h"'),
        "slashes": ("core/cut/grid.cpp", '#include "haloplot//cut/cut.h"'),
        "internal": ("core/cut/grid.cpp", '#include "cut/grid_walk.h"'),
        "copy": ("core/CMakeLists.txt", "file(COPY include/ DESTINATION ${PROJECT_BINARY_DIR})"),
        "link": ("core/CMakeLists.txt",
                 "execute_process(COMMAND ln -s ${CMAKE_CURRENT_SOURCE_DIR} haloplot)"),
    },
}


def main(argv):
    src, mode = argv[1], argv[2]
    check = {"layers": check_layers, "paths": check_paths}[mode]
    if len(argv) > 4 and argv[3] == "plant":
        kinds = list(PLANTS[mode]) if argv[4] == "all" else [argv[4]]
        if any(k not in PLANTS[mode] for k in kinds):
            print("plant kinds for %s: all %s" % (mode, " ".join(PLANTS[mode])))
            return 2
        return max(plant(src, mode, check, k) for k in kinds)
    n, bad = check(src)
    for b in bad:
        print("FAILED: " + b)
    print("%s: %d includes checked, %d failed" % (mode, n, len(bad)))
    return 0 if n > 0 and not bad else 1


def plant(src, mode, check, kind):
    rel, text = PLANTS[mode][kind]
    copy = tempfile.mkdtemp()
    try:
        for part in PARTS:
            if os.path.isdir(os.path.join(src, part)):
                shutil.copytree(os.path.join(src, part), os.path.join(copy, part),
                                ignore=shutil.ignore_patterns("build"))
        path = os.path.join(copy, rel)
        body = open(path, encoding="utf-8").read()
        open(path, "w", encoding="utf-8").write(text + "\n" + body)
        n, bad = check(copy)
    finally:
        shutil.rmtree(copy)
    caught = [b for b in bad if b.startswith(rel)]
    print("%s, planted %s in %s: %s" % (mode, kind, rel,
          "caught: " + caught[0] if caught else "NOT CAUGHT"))
    return 0 if caught and len(caught) == len(bad) else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
