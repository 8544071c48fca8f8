#!/usr/bin/env bash
# The Bézier trefoil against its 10,000-edge flattening: memory and time of the curve stages
# against CUT and DRAW, as ratios in one run. Prints the Markdown paragraph docs/curves.md
# quotes under "Measured".
set -euo pipefail
cd "$(dirname "$0")/.."
cmake --preset host >/dev/null
cmake --build --preset host -j "$(nproc)" --target curve_bench >/dev/null
cpu=$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')
build/host/tests/bench/curve_bench
echo
echo "(\`bash tools/bench_curves.sh\`, $(date -u '+%Y-%m-%d'), ${cpu}.)"
