#!/usr/bin/env bash
# The README's test command: install what is missing, build every preset the tests need
# (host, host-asan, firmware for the STM32F405, firmware-mps2 for the second board, fuzz) and
# run CTest on the host presets and the fuzz targets (each replays its seed corpus, then
# explores for 20 seconds).
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install_deps.sh test
jobs=$(nproc)
for preset in host host-asan firmware firmware-mps2 fuzz; do
  echo "== configure and build: $preset"
  cmake --preset "$preset" >/dev/null
  cmake --build --preset "$preset" -j "$jobs"
done
for preset in host host-asan fuzz; do
  echo "== ctest: $preset"
  ctest --preset "$preset" -j "$jobs"
done
