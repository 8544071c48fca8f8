#!/usr/bin/env bash
# The README's main command: build the host tool and plot the demo scene (the HALO paper's
# Figure 4, 28 x 28 cubes) to out/: the scene, its CUTSET, the visible spans, SVG and PNG.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install_deps.sh demo || echo "continuing without the optional PNG converter"
cmake --preset host >/dev/null
cmake --build --preset host -j "$(nproc)" --target haloplot
tool=build/host/host_sim/haloplot
mkdir -p out
"$tool" demo-scene --cubes 28 -o out/demo.edges
"$tool" plot out/demo.edges --halo 50 -o out/demo.svg --spans out/demo.spans --cut out/demo.cut --stats
if command -v rsvg-convert >/dev/null 2>&1; then
  rsvg-convert -w 1600 -b white out/demo.svg -o out/demo.png
  echo "wrote out/demo.png"
fi
echo "wrote out/demo.edges out/demo.cut out/demo.spans out/demo.svg"
