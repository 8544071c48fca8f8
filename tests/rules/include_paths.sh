#!/usr/bin/env bash
# Headers are where they are included from: every `#include "haloplot/..."` (or <haloplot/...>)
# in the tree names a file at that path under core/include or hal/include, and every internal
# include of the core ("sort/in_place_sort.h") names a file under core/; no CMake file makes
# links (a folder of links made at configure time is what this replaced). `plant` copies the
# tree with one include of a header that is not there and must fail.
# Usage: include_paths.sh SOURCE_DIR [plant]
set -u
src="$1"
if [ "${2:-}" = plant ]; then
  copy=$(mktemp -d)
  trap 'rm -rf "$copy"' EXIT
  cp -r "$src/core" "$src/hal" "$copy/"
  sed -i '1i #include "haloplot/cut/cut_grid.h"' "$copy/core/cut/grid.cpp"
  src="$copy"
fi
fail=0 checked=0
while IFS= read -r f; do
  while IFS= read -r inc; do
    checked=$((checked + 1))
    case "$inc" in
      haloplot/*) [ -f "$src/core/include/$inc" ] || [ -f "$src/hal/include/$inc" ] ||
        { echo "FAILED: ${f#"$src"/} includes $inc, which is not under core/include or hal/include"; fail=$((fail + 1)); } ;;
      *) [ -f "$src/core/$inc" ] ||
        { echo "FAILED: ${f#"$src"/} includes $inc, which is not under core/"; fail=$((fail + 1)); } ;;
    esac
  done < <(grep -hoE '^#include ["<][a-z0-9_]+/[a-z0-9_/]+\.h[">]' "$f" | sed -E 's/^#include .//; s/.$//' |
           grep -E "^(haloplot|$(ls "$src/core" | tr '\n' '|' | sed 's/|$//'))/")
done < <(find "$src/core" "$src/hal" "$src/firmware" "$src/host_sim" "$src/tests" "$src/examples" \
           \( -name '*.h' -o -name '*.cpp' \) 2> /dev/null)
links=$(grep -rlE 'CREATE_LINK|create_symlink' --include=CMakeLists.txt --include='*.cmake' "$src" 2> /dev/null |
        grep -v '/build/')
[ -z "$links" ] || { echo "FAILED: CMake files that make links: $links"; fail=$((fail + 1)); }
echo "include_paths: $checked includes checked, $fail failed"
[ "$checked" -gt 0 ] && [ "$fail" -eq 0 ]
