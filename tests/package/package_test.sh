#!/usr/bin/env bash
# The installed package, used from outside the tree: installs BUILD_DIR into a scratch prefix,
# then configures and builds a consumer project against it with find_package(haloplot).
#   host:  the consumer runs CUT and DRAW and checks them against its own brute force;
#   cross: the consumer is a Cortex-M4 image built with the cross toolchain, and must pass the
#          firmware's symbol gate (no heap, no exceptions, no software floating point).
# Usage: package_test.sh host|cross SOURCE_DIR BUILD_DIR
set -euo pipefail
mode=$1 src=$2 build=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build" --prefix "$work/prefix" > "$work/install.log"
[ -f "$work/prefix/lib/cmake/haloplot/haloplotConfig.cmake" ] || { echo "no package config installed"; exit 1; }
[ -f "$work/prefix/include/haloplot/cut/cut.h" ] || { echo "no headers installed"; exit 1; }
# The package carries the public headers and what they include, and nothing else: each
# installed header compiles on its own against the prefix alone, and a header only the core's
# sources use is not there.
if [ "$mode" = host ]; then
  [ ! -e "$work/prefix/include/haloplot/sort/in_place_sort.h" ] ||
    { echo "an internal header (sort/in_place_sort.h) was installed"; exit 1; }
  n=0
  while IFS= read -r h; do
    rel=${h#"$work/prefix/include/haloplot/"}
    printf '#include "%s"\n' "$rel" |
      c++ -std=c++17 -fsyntax-only -x c++ -I "$work/prefix/include/haloplot" \
        -I "$work/prefix/include/haloplot/hal" - ||
      { echo "installed header $rel does not compile on its own from the prefix"; exit 1; }
    n=$((n + 1))
  done < <(find "$work/prefix/include/haloplot" -name '*.h' | sort)
  echo "package headers: $n, each compiles on its own"
fi
args=(-S "$src/tests/package/${mode}_consumer" -B "$work/consumer" -DCMAKE_PREFIX_PATH="$work/prefix"
      -DCMAKE_BUILD_TYPE=Release)
[ "$mode" = cross ] && args+=(-DCMAKE_TOOLCHAIN_FILE="$src/cmake/arm-none-eabi.cmake")
cmake "${args[@]}" > "$work/configure.log" || { cat "$work/configure.log"; exit 1; }
cmake --build "$work/consumer" > "$work/build.log" 2>&1 || { cat "$work/build.log"; exit 1; }
if [ "$mode" = host ]; then
  "$work/consumer/consumer"
else
  cmake -DNM=arm-none-eabi-nm -DIMAGE="$work/consumer/image" -P "$src/firmware/check_symbols.cmake"
  arm-none-eabi-nm "$work/consumer/image" | grep -q " T run_cut\| T _ZN8haloplot7run_cut" ||
    { echo "the image does not contain the core's CUT"; exit 1; }
  echo "cross consumer: linked $(arm-none-eabi-size -A "$work/consumer/image" | awk '/^.text/ {print $2}') bytes of text"
fi
