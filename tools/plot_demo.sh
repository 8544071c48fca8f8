#!/usr/bin/env bash
# The README's main command: build the host tool, plot the demo scene (the HALO paper's
# Figure 4, 28 x 28 cubes) and simulate the plotter drawing it. Writes to out/:
#   demo.edges  demo.cut  demo.spans  demo.svg  demo.png     the haloed picture
#   demo.trace  demo.replay.svg  demo.replay.png              the motors' steps, replayed
#   demo.btrace                                               the same trace, binary form
#   demo.gcode  demo.hpgl                                     for plotters with other firmware
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install_deps.sh demo || echo "continuing without the optional PNG converter"
cmake --preset host >/dev/null
cmake --build --preset host -j "$(nproc)" --target haloplot
tool=build/host/host_sim/haloplot
mkdir -p out
"$tool" demo-scene --cubes 28 -o out/demo.edges
"$tool" plot out/demo.edges --halo 50 -o out/demo.svg --spans out/demo.spans --cut out/demo.cut --stats
"$tool" sim scenes/demo.job -o out/demo.trace --gcode out/demo.gcode --hpgl out/demo.hpgl --stats
"$tool" sim scenes/demo.job -o out/demo.btrace --binary
echo "trace: $(wc -c < out/demo.trace) bytes as text, $(wc -c < out/demo.btrace) binary (demo.btrace)"
"$tool" replay out/demo.trace -o out/demo.replay.svg --stats
if command -v rsvg-convert >/dev/null 2>&1; then
  rsvg-convert -w 1600 -b white out/demo.svg -o out/demo.png
  rsvg-convert -w 1600 -b white out/demo.replay.svg -o out/demo.replay.png
  echo "wrote out/demo.png out/demo.replay.png"
fi
echo "wrote out/demo.{edges,cut,spans,svg,trace,replay.svg,gcode,hpgl}"
