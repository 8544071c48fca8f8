#!/usr/bin/env bash
# The demo's deterministic figures, as the docs quote them: runs the tool on the demo (the
# HALO paper's Figure 4, scenes/demo.job) and prints key=value lines, numbers formatted as in
# the text (1,234,567; ratios to the shown decimals). The README and docs/ quote them between
# <!-- fig:KEY --> and <!-- /fig -->; tools/update_doc_figures.sh rewrites those from this
# output, and the CTest doc_figures fails when one differs. About 15 s (four simulations).
# Usage: tools/demo_figures.sh [HALOPLOT]   (default build/host/host_sim/haloplot)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
tool="${1:-$root/build/host/host_sim/haloplot}"
case "$tool" in /*) ;; *) tool="$PWD/$tool" ;; esac
[ -x "$tool" ] || { echo "demo_figures: no tool at $tool (build it: cmake --build --preset host --target haloplot)" >&2; exit 2; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cd "$work"
"$tool" demo-scene --cubes 28 -o demo.edges
"$tool" plot demo.edges --halo 50 -o demo.svg --spans demo.spans --stats 2> plot.stats
# The committed job names ../out/demo.edges; here the scene sits beside the job.
sed 's#^scene .*#scene demo.edges#' "$root/scenes/demo.job" > demo.job
"$tool" sim demo.job -o demo.trace --stats 2> sim.stats
"$tool" sim demo.job -o demo.btrace --binary
"$tool" sim demo.job --arena 65536 -o a64.trace --stats 2> a64.stats
"$tool" sim demo.job --arena 98304 -o a96.trace --stats 2> a96.stats
stat() { sed -n "s/^$2=//p" "$1" | head -1; }
awk -v e="$(stat plot.stats edges)" -v k="$(stat plot.stats crossings)" \
    -v sp="$(stat plot.stats spans)" \
    -v s0="$(stat sim.stats steps_0)" -v s1="$(stat sim.stats steps_1)" \
    -v tb="$(wc -c < demo.trace)" -v bb="$(wc -c < demo.btrace)" \
    -v lifts="$(stat sim.stats pen_lifts)" -v up="$(stat sim.stats pen_up_length)" \
    -v naive="$(stat sim.stats naive_pen_up_length)" -v down="$(stat sim.stats pen_down_length)" \
    -v ps="$(stat sim.stats plot_s)" \
    -v b64="$(stat a64.stats bands)" -v up64="$(stat a64.stats pen_up_length)" \
    -v lifts64="$(stat a64.stats pen_lifts)" -v ps64="$(stat a64.stats plot_s)" \
    -v tb64="$(wc -c < a64.trace)" \
    -v b96="$(stat a96.stats bands)" -v up96="$(stat a96.stats pen_up_length)" \
    -v ps96="$(stat a96.stats plot_s)" '
function commas(n,   s, out) {
  s = sprintf("%d", n); out = ""
  while (length(s) > 3) { out = "," substr(s, length(s) - 2) out; s = substr(s, 1, length(s) - 3) }
  return s out
}
BEGIN {
  steps = s0 + s1
  print "demo_edges=" commas(e)
  print "demo_crossings=" commas(k)
  print "demo_spans=" commas(sp)
  print "trace_steps=" commas(steps)
  print "trace_bytes=" commas(tb)
  printf "trace_bytes_per_step=%.2f\n", tb / steps
  print "btrace_bytes=" commas(bb)
  printf "btrace_bytes_per_step=%.2f\n", bb / steps
  print "pen_lifts=" commas(lifts)
  print "pen_down=" commas(down)
  print "pen_up_naive=" commas(naive)
  print "pen_up=" commas(up)
  printf "pen_up_ratio=%.1f\n", naive / up
  print "plot_s=" commas(int(ps + 0.5))
  print "a64_bands=" commas(b64)
  print "a64_pen_lifts=" commas(lifts64)
  print "a64_pen_up=" commas(up64)
  printf "a64_pen_up_ratio=%.2f\n", up64 / up
  print "a64_plot_s=" commas(int(ps64 + 0.5))
  printf "a64_plot_ratio=%.2f\n", ps64 / ps
  print "a64_trace_bytes=" commas(tb64)
  printf "a64_trace_mb=%.1f\n", tb64 / 1e6
  print "a96_bands=" commas(b96)
  printf "a96_pen_up_ratio=%.2f\n", up96 / up
  printf "a96_plot_ratio=%.2f\n", ps96 / ps
}'
