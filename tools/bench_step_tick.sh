#!/usr/bin/env bash
# Instructions per step event in the step tick on the host, counted by callgrind (repeatable,
# unlike time). Usage: tools/bench_step_tick.sh [build dir, default build/host]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/host}
cmake --build "$build" --target step_tick_bench >/dev/null
out=$(mktemp -d)
valgrind --tool=callgrind --callgrind-out-file="$out/cg" --toggle-collect='isr_tick*' \
  "$build/tests/bench/step_tick_bench" > "$out/stdout" 2> "$out/stderr"
events=$(sed -n 's/^events=//p' "$out/stdout")
ir=$(callgrind_annotate "$out/cg" 2>/dev/null | awk '/PROGRAM TOTALS/ {gsub(",", "", $1); print $1}')
echo "step events: $events"
echo "instructions in the tick: $ir"
echo "instructions per step event: $(( ir / events ))"
rm -rf "$out"
