#!/usr/bin/env bash
# The README's test command: install what is missing, build every preset the tests need
# (host, host-asan, firmware) and run CTest on both host presets.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install_deps.sh test
jobs=$(nproc)
for preset in host host-asan firmware; do
  echo "== configure and build: $preset"
  cmake --preset "$preset" >/dev/null
  cmake --build --preset "$preset" -j "$jobs"
done
for preset in host host-asan; do
  echo "== ctest: $preset"
  ctest --preset "$preset" -j "$jobs"
done
