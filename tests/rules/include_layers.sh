#!/usr/bin/env bash
# Layers point one way: a file may include its own folder or a folder below its own, never one
# above. core/'s folders from the bottom:
#   0 status geometry sort hal   1 memory   2 scene view view2d   3 cut   4 draw
#   5 curve solid   6 surface   7 motion   8 trace   9 band   10 job   11 protocol   12 controller
# (folders of one rank do not include each other either). In host_sim/, cli/ is the top: no
# other folder includes it (only the command line reads Options). firmware/ includes nothing
# from tests/, and its CMake puts no tests/ folder on an include path. No exceptions.
# `plant core|host_sim|firmware` copies the tree with one upward include in that part (cut/
# including job/, pipeline/ including cli/, a self-test including tests/) and must fail.
# Usage: include_layers.sh SOURCE_DIR [plant PART]
set -u
src="$1"
if [ "${2:-}" = plant ]; then
  copy=$(mktemp -d)
  trap 'rm -rf "$copy"' EXIT
  cp -r "$src/core" "$src/host_sim" "$src/firmware" "$copy/"
  case "${3:-}" in
    core) sed -i '1i #include "haloplot/job/job.h"' "$copy/core/cut/grid.cpp" ;;
    host_sim) sed -i '1i #include "cli/options.h"' "$copy/host_sim/pipeline/triangulate.cpp" ;;
    firmware) sed -i '1i #include "unit/check.h"' "$copy/firmware/selftest/hello.cpp" ;;
    *) echo "plant what? core, host_sim or firmware"; exit 2 ;;
  esac
  src="$copy"
fi
rank() {
  case "$1" in
    status | geometry | sort | hal) echo 0 ;; memory) echo 1 ;; scene | view | view2d) echo 2 ;;
    cut) echo 3 ;; draw) echo 4 ;; curve | solid) echo 5 ;; surface) echo 6 ;; motion) echo 7 ;;
    trace) echo 8 ;; band) echo 9 ;; job) echo 10 ;; protocol) echo 11 ;; controller) echo 12 ;;
    *) echo "" ;;
  esac
}
fail=0 pass=0
bad() { echo "FAILED: $*"; fail=$((fail + 1)); }
while IFS= read -r f; do
  folder=$(basename "$(dirname "$f")")
  own=$(rank "$folder")
  [ -n "$own" ] || continue
  # Public headers are included as "haloplot/<folder>/...", internal ones as "<folder>/...".
  for t in $(grep -oE '#include "(haloplot/)?[a-z0-9_]+/' "$f" | sed -E 's|.*"(haloplot/)?||; s|/$||' | sort -u); do
    [ "$t" = "$folder" ] && continue
    r=$(rank "$t")
    if [ -n "$r" ] && [ "$r" -lt "$own" ]; then pass=$((pass + 1)); else
      bad "${f#"$src"/} includes $t/, a layer above its own"; fi
  done
done < <(find "$src/core" -name '*.h' -o -name '*.cpp')
while IFS= read -r f; do
  case "$f" in "$src"/host_sim/cli/*) continue ;; esac
  if grep -q '#include "cli/' "$f"; then bad "${f#"$src"/} includes cli/, the top layer"; else
    pass=$((pass + 1)); fi
done < <(find "$src/host_sim" -name '*.h' -o -name '*.cpp')
while IFS= read -r f; do
  if grep -qE '#include "(unit|support|reference|tests|bench)/' "$f"; then
    bad "${f#"$src"/} includes the tests"; else pass=$((pass + 1)); fi
done < <(find "$src/firmware" -name '*.h' -o -name '*.cpp')
while IFS= read -r f; do
  if grep -qE 'include_directories\(.*tests' "$f"; then
    bad "${f#"$src"/} puts a tests/ folder on the firmware's include path"; fi
done < <(find "$src/firmware" -name CMakeLists.txt -o -name '*.cmake')
echo "include_layers: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
