#!/usr/bin/env bash
# The installed package, used from outside the tree: installs BUILD_DIR into a scratch prefix,
# then configures and builds a consumer project against it with find_package(haloplot).
#   host:  the consumer runs CUT and DRAW and checks them against its own brute force;
#   cross: the consumer is a Cortex-M4 image built with the cross toolchain, and must pass the
#          firmware's symbol gate (no heap, no exceptions, no software floating point);
#   both:  the consumer instantiates the motion runner (motion/motion_runner.h) on a board of
#          its own, so the installed header is enough for it (the host one runs it).
# Usage: package_test.sh host|cross SOURCE_DIR BUILD_DIR
set -euo pipefail
mode=$1 src=$2 build=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build" --prefix "$work/prefix" > "$work/install.log"
[ -f "$work/prefix/lib/cmake/haloplot/haloplotConfig.cmake" ] || { echo "no package config installed"; exit 1; }
[ -f "$work/prefix/include/haloplot/cut/cut.h" ] || { echo "no headers installed"; exit 1; }
# The package carries the public headers and what they include, and nothing else: each
# installed header compiles on its own as <haloplot/...> with the prefix's one include
# directory, and a header only the core's sources use is not there. No installed header is
# reached by a bare generic name: every header the package holds is under include/haloplot/.
if [ "$mode" = host ]; then
  [ ! -e "$work/prefix/include/haloplot/sort/in_place_sort.h" ] ||
    { echo "an internal header (sort/in_place_sort.h) was installed"; exit 1; }
  n=0
  while IFS= read -r h; do
    rel=${h#"$work/prefix/include/"}
    printf '#include <%s>\n' "$rel" |
      c++ -std=c++17 -fsyntax-only -x c++ -I "$work/prefix/include" - ||
      { echo "installed header <$rel> does not compile on its own from the prefix's one include directory"; exit 1; }
    n=$((n + 1))
  done < <(find "$work/prefix/include/haloplot" -name '*.h' | sort)
  stray=$(find "$work/prefix/include" -name '*.h' -not -path "$work/prefix/include/haloplot/*")
  [ -z "$stray" ] || { echo "headers outside include/haloplot/: $stray"; exit 1; }
  echo "package headers: $n, each compiles on its own as <haloplot/...>"
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
  # Into a file first: grep -q stops reading at its match, and under pipefail nm's broken pipe
  # would then fail the test.
  arm-none-eabi-nm "$work/consumer/image" > "$work/image.nm"
  grep -q " T run_cut\| T _ZN8haloplot7run_cut" "$work/image.nm" ||
    { echo "the image does not contain the core's CUT"; exit 1; }
  # The motion runner from the installed header, on the consumer's own board (mostly inlined
  # into the consumer's loop; its service() stays a function).
  grep -q "MotionRunner" "$work/image.nm" ||
    { echo "the image does not contain the motion runner"; exit 1; }
  echo "cross consumer: linked $(arm-none-eabi-size -A "$work/consumer/image" | awk '/^.text/ {print $2}') bytes of text"
fi
