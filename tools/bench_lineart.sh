#!/usr/bin/env bash
# Hidden lines against Blender's Line Art, one run: for each model (a pair of cubes, the demo's
# 10 x 10 cubes, tori and UV spheres of 2k, 20k and 200k triangles, generated as OBJ), rounds
# that alternate Line Art with one thread (`blender -t 1`), Line Art on every core (`-t 0`),
# haloplot's `plot --mode hidden-removed --threads 1` and `--threads $(nproc)`, the same view
# (--view 30,25; tools/bench_lineart.py sets up the matching orthographic camera and Line Art
# modifier). Writes the section "13. Against Blender's Line Art" of
# docs/reports/performance.md in place (or prints it with --print). Installs Debian's
# `blender` where it can (as root with apt-get); without it, says so and writes nothing.
# Usage: tools/bench_lineart.sh [--print] [ROUNDS [RUNS]]   (RUNS: timings a round, each side)
set -euo pipefail
cd "$(dirname "$0")/.."
print=0
[ "${1:-}" = --print ] && { print=1; shift; }
rounds=${1:-3} runs=${2:-5}
if ! command -v blender >/dev/null 2>&1 && [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null; then
  echo "bench_lineart: installing Debian's blender (apt-get)" >&2
  DEBIAN_FRONTEND=noninteractive apt-get install -y blender >&2 || true
fi
if ! command -v blender >/dev/null 2>&1; then
  echo "bench_lineart: blender is not installed (as root: apt-get install blender);" \
    "section 13 of docs/reports/performance.md left as it is" >&2
  exit 0
fi
cmake --preset host >/dev/null
cmake --build --preset host -j 2 --target haloplot >/dev/null
tool=$PWD/build/host/host_sim/haloplot
all=$(nproc)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# shellcheck source=../tests/support/model_files.sh
source tests/support/model_files.sh
{ box 0 1 0 1 0 -1 1; box 0.5 1.5 0.2 1.2 -1.6 -2.6 9; } > "$work/cube_pair.obj"
"$tool" demo-scene --cubes 10 -o "$work/cubes_10x10.obj" >/dev/null
torus_obj 1.5 0.6 50 20 > "$work/torus_2k.obj"
torus_obj 1.5 0.6 158 63 > "$work/torus_20k.obj"
torus_obj 1.5 0.6 500 200 > "$work/torus_200k.obj"
uv_sphere_obj 1 40 26 > "$work/sphere_2k.obj"
uv_sphere_obj 1 125 81 > "$work/sphere_20k.obj"
uv_sphere_obj 1 400 251 > "$work/sphere_200k.obj"
models="cube_pair cubes_10x10 torus_2k sphere_2k torus_20k sphere_20k torus_200k sphere_200k"
line_art() {  # MODEL THREADS(0: all) ROUND
  blender -b --factory-startup -t "$2" --python tools/bench_lineart.py -- "$work/$1.obj" 30 25 \
    "$runs" "$work/la.$1.$2.$3" cull > "$work/la.$1.$2.$3.log" 2>&1
}
haloplot() {  # MODEL THREADS: one line a run, "stage_ms stage_cpu_ms plot_ms"
  local t0 t1
  for _ in $(seq "$runs"); do
    t0=$EPOCHREALTIME
    "$tool" plot "$work/$1.obj" --mode hidden-removed --view 30,25 -o "$work/p.svg" \
      --threads "$2" --stats 2> "$work/stats"
    t1=$EPOCHREALTIME
    echo "$(sed -n 's/^hidden_ms=//p' "$work/stats") $(sed -n 's/^hidden_cpu_ms=//p' "$work/stats")" \
      "$(echo "($t1 - $t0) * 1000" | bc)"
  done >> "$work/hp.$1.$2"
}
load_before=$(cut -d' ' -f1-3 /proc/loadavg)
for r in $(seq "$rounds"); do
  for m in $models; do
    line_art "$m" 1 "$r"
    line_art "$m" 0 "$r"
    haloplot "$m" 1
    haloplot "$m" "$all"
  done
done
load_after=$(cut -d' ' -f1-3 /proc/loadavg)
min() { sort -g | head -1; }
# Line Art, THREADS (1 or 0) and SETTING (default, culled): "eval_wall eval_cpu total load" (ms),
# each the least of its runs; Blender's timers print one set an evaluation, in the order
# tools/bench_lineart.py writes its lines.
line_art_best() {
  local r ew ec tot ld
  for r in $(seq "$rounds"); do
    awk -v s="$3" '$1 == s' "$work/la.$1.$2.$r" > "$work/mine"
    awk -v s="$3" '/^Line art loading time:/ { n++; if ((n % 2 == 1) == (s == "default"))
      print $5 * 1000 }' "$work/la.$1.$2.$r.log" > "$work/load"
    awk -v s="$3" '/^Line art total time:/ { n++; if ((n % 2 == 1) == (s == "default"))
      print $5 * 1000 }' "$work/la.$1.$2.$r.log" > "$work/total"
    paste -d' ' "$work/mine" "$work/total" "$work/load"
  done > "$work/la_runs"
  ew=$(cut -d' ' -f2 "$work/la_runs" | min)
  ec=$(cut -d' ' -f3 "$work/la_runs" | min)
  tot=$(cut -d' ' -f4 "$work/la_runs" | min)
  ld=$(cut -d' ' -f5 "$work/la_runs" | min)
  echo "$ew $ec $tot $ld"
}
hp_best() {  # MODEL THREADS: "stage_ms stage_cpu_ms plot_ms"
  echo "$(cut -d' ' -f1 "$work/hp.$1.$2" | min) $(cut -d' ' -f2 "$work/hp.$1.$2" | min)" \
    "$(cut -d' ' -f3 "$work/hp.$1.$2" | min)"
}
r2() { echo "scale=2; $1 / $2" | bc | sed 's/^\./0./'; }
f1() { if [ "$(echo "$1 < 10" | bc)" = 1 ]; then printf '%.2f' "$1"; else printf '%.1f' "$1"; fi; }
same_lines=yes
{
  echo "| model | triangles | Line Art CPU ms | Line Art ms (loading) | haloplot stage CPU ms | haloplot stage ms | haloplot plot ms | **CPU ratio** | ratio | ratio to plot |"
  echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
  for m in $models; do
    read -r _ ec tot ld <<< "$(line_art_best "$m" 1 default)"
    read -r _ ecc totc _ <<< "$(line_art_best "$m" 1 culled)"
    read -r hs hc hp <<< "$(hp_best "$m" 1)"
    "$tool" plot "$work/$m.obj" --mode hidden-removed --view 30,25 -o "$work/p.svg" --stats \
      2> "$work/stats"
    tris=$(sed -n 's/^triangles=//p' "$work/stats")
    [ "$(grep -c "^drawn default $(sed -n 's/^drawn culled //p' "$work/la.$m.1.1")" \
      "$work/la.$m.1.1")" = 1 ] || same_lines=NO
    [ "$(echo "$ec < 3 * $hc" | bc)" = 1 ] && echo "$m ($(r2 "$ec" "$hc"))" >> "$work/under3"
    [ "$(echo "$ecc < 3 * $hc" | bc)" = 1 ] && echo "$m ($(r2 "$ecc" "$hc"))" >> "$work/under3.culled"
    echo "| $m | $tris | $(f1 "$ec") / $(f1 "$ecc") | $(f1 "$tot") / $(f1 "$totc") ($(f1 "$ld")) |" \
      "$(f1 "$hc") | $(f1 "$hs") | $(f1 "$hp") | **$(r2 "$ec" "$hc") / $(r2 "$ecc" "$hc")** |" \
      "$(r2 "$tot" "$hs") / $(r2 "$totc" "$hs") | $(r2 "$tot" "$hp") / $(r2 "$totc" "$hp") |"
  done
} > "$work/one.md"
{
  echo "| model | Line Art ms, all cores | haloplot stage ms, all cores | **ratio** | Line Art 1 / all | haloplot 1 / all |"
  echo "|---|---:|---:|---:|---:|---:|"
  for m in $models; do
    read -r _ _ tot1 _ <<< "$(line_art_best "$m" 1 default)"
    read -r _ _ totn _ <<< "$(line_art_best "$m" 0 default)"
    read -r _ _ totnc _ <<< "$(line_art_best "$m" 0 culled)"
    read -r hs1 _ _ <<< "$(hp_best "$m" 1)"
    read -r hsn _ _ <<< "$(hp_best "$m" "$all")"
    [ "$(echo "$totn <= $hsn" | bc)" = 1 ] && echo "$m" >> "$work/behind"
    echo "| $m | $(f1 "$totn") / $(f1 "$totnc") | $(f1 "$hsn") |" \
      "**$(r2 "$totn" "$hsn") / $(r2 "$totnc" "$hsn")** | $(r2 "$tot1" "$totn") | $(r2 "$hs1" "$hsn") |"
  done
} > "$work/all.md"
section() {
  echo "## 13. Against Blender's Line Art"
  echo
  echo "Generated by \`bash tools/bench_lineart.sh\` on $(date -u '+%Y-%m-%d %H:%M UTC'), $all cores"
  echo "($(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')), $(blender --version 2>/dev/null | head -1)"
  echo "(Debian's \`blender\`), load average $load_before before and $load_after after (the machine"
  echo "is shared: read the CPU columns). Each model is timed in $rounds rounds that alternate Line Art"
  echo "with one thread (\`blender -t 1\`), Line Art on every core (\`-t 0\`), haloplot with"
  echo "\`--threads 1\` and with \`--threads $all\`, $runs timings of each a round; every figure is the"
  echo "least of its $((rounds * runs)) timings."
  echo
  echo "What is compared. The same mesh (the OBJ, turned z up as haloplot reads it) seen along the"
  echo "same direction (\`--view 30,25\`; an orthographic camera in Blender), and the same lines:"
  echo "haloplot's \`plot --mode hidden-removed\` draws the visible parts of the contours, of every"
  echo "edge between faces that are not flat, and of the lines where faces cross; Line Art's"
  echo "modifier (tools/bench_lineart.py) draws its visible contours, creases at a threshold of"
  echo "179.9 degrees (every edge with a bend) and intersections. Line Art runs two ways, each"
  echo "figure written *default / culled*: its default, back faces kept, as a user runs it (and as"
  echo "issue 48 measured it), and with back-face culling, its fastest setting that draws the same"
  echo "lines on these closed meshes (the same strokes and points both ways: **$same_lines**)."
  echo
  echo "- *Line Art CPU ms*: the CPU time of Blender's process while it re-evaluates the Grease"
  echo "  Pencil object, which is only the Line Art modifier (the mesh is evaluated once before):"
  echo "  from the evaluated mesh to its strokes in the Grease Pencil frame: loading the mesh into"
  echo "  Line Art (projection, feature edges), the triangles into its grid with their"
  echo "  intersections, the occlusion, the chaining, the strokes. A warm process: its first"
  echo "  evaluation is not timed. *Line Art ms*: Line Art's own timer for the same computation"
  echo "  but the strokes (\`bpy.app.debug_value = 4000\`, \"Line art total time\"), wall clock; in"
  echo "  brackets its \"loading time\" (default), the mesh into Line Art's buffers. Wall and CPU"
  echo "  times part where the shared machine's other work takes the core: read the CPU columns."
  echo "- *haloplot stage*: \`--stats\`' hidden_ms (wall) and hidden_cpu_ms (CPU): the hidden-line"
  echo "  stage from the projected, welded mesh to the drawn pieces in the host's vectors: the"
  echo "  topology (its edge table), CUT, the QI walk, the intersection lines, the pieces; each run"
  echo "  a fresh process, so its first-touch costs are in it. Reading the OBJ, welding, the"
  echo "  creases' choice and the projection come before it (Line Art does the last two in its"
  echo "  loading). *haloplot plot ms*: the whole \`plot ... -o OUT.svg\` process, start to exit,"
  echo "  reading the text file and writing the SVG included, which nothing on Blender's side"
  echo "  includes."
  echo "- **CPU ratio**: Line Art CPU / haloplot stage CPU, one thread each: the issue's aim is at"
  echo "  least 3 on every model. *ratio*: the same in wall time, Line Art's timer against hidden_ms."
  echo "  *ratio to plot*: Line Art's timer against haloplot's whole process."
  echo
  echo "Where the time goes: the hidden lines' CUT pairs only the edges a crossing behind which can"
  echo "change a count of faces (on these smooth meshes a few in a thousand), so the QI walk, the"
  echo "topology and the intersection lines now take most of the stage. Below 2k triangles first-touch"
  echo "page faults were a fifth of the stage; the"
  echo "host now keeps a small model's freed heap for it and maps a small buffer fresh (section"
  echo "written with that change)."
  echo
  echo "One thread:"
  echo
  cat "$work/one.md"
  echo
  if [ -s "$work/under3" ]; then
    echo "**The aim (a CPU ratio of at least 3 on every model) is not met** against Line Art's default"
    echo "on: $(paste -sd, "$work/under3" | sed 's/,/, /g'); against back-face culling on:"
    echo "$( [ -s "$work/under3.culled" ] && paste -sd, "$work/under3.culled" | sed 's/,/, /g' || echo none)."
  else
    echo "**The aim (a CPU ratio of at least 3 on every model) is met against Line Art's default**;"
    echo "against back-face culling it is not on:"
    echo "$( [ -s "$work/under3.culled" ] && paste -sd, "$work/under3.culled" | sed 's/,/, /g' || echo none)."
  fi
  echo
  echo "Every core ($all), wall time (Line Art's timer against hidden_ms; the issue asks haloplot"
  echo "ahead, a ratio above 1). Wall time is all there is to compare here; with the load above"
  echo "the core count, neither side's 1 / all speed-up is reliable:"
  echo
  cat "$work/all.md"
  echo
  if [ -s "$work/behind" ]; then
    echo "haloplot with every thread is **not** ahead of Line Art with every thread on: $(paste -sd, "$work/behind" | sed 's/,/, /g')."
  else
    echo "haloplot with every thread is ahead of Line Art (default) with every thread on every model."
  fi
}
if [ "$print" = 1 ]; then section; exit 0; fi
section > "$work/section.md"
awk -v file="$work/section.md" '
  /^## 13\. Against Blender/ { while ((getline l < file) > 0) print l; skip = 1; next }
  skip && /^## / { skip = 0 }
  !skip { print }
  ' docs/reports/performance.md > "$work/perf.md"
grep -q "^## 13\. Against Blender" docs/reports/performance.md || { echo; cat "$work/section.md"; } >> "$work/perf.md"
cp "$work/perf.md" docs/reports/performance.md
cat "$work/section.md"
