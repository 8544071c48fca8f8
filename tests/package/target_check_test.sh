#!/usr/bin/env bash
# The package checks its consumer's CPU (cmake/haloplotConfigVersion.cmake.in): the library
# built and installed for a Cortex-M33 (hard float) with a toolchain file written here, then the
# consumer project of package_cross (tests/package/cross_consumer) configured against it:
#   - for a Cortex-M0+ (soft float): the configure must fail, naming both CPUs;
#   - for the M33 with soft float: must fail, naming both float ABIs;
#   - for the M33 with the package's flags: must configure, build and link, for ARMv8-M;
#   - the M0+ again with HALOPLOT_ACCEPT_ANY_TARGET=ON: configures (the refusal above was the
#     target check's, and the way past it works);
#   - the stack each plotting entry takes on the M33, against docs/porting.md
#     (tests/firmware/stack_probe.sh).
# Usage: target_check_test.sh SOURCE_DIR
set -euo pipefail
src=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAILED: $*"; exit 1; }
toolchain() {  # toolchain NAME FLAGS: a bare-metal toolchain file of the user's own
  cat > "$work/$1.cmake" <<TOOLCHAIN
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR arm)
set(CMAKE_C_COMPILER arm-none-eabi-gcc)
set(CMAKE_CXX_COMPILER arm-none-eabi-g++)
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)
set(CMAKE_C_FLAGS_INIT "$2 -ffunction-sections -fdata-sections")
set(CMAKE_CXX_FLAGS_INIT "$2 -ffunction-sections -fdata-sections")
set(CMAKE_EXE_LINKER_FLAGS_INIT "-nostartfiles -Wl,--gc-sections")
TOOLCHAIN
}
toolchain m33 "-mcpu=cortex-m33 -mthumb -mfloat-abi=hard -mfpu=fpv5-sp-d16"
toolchain m33soft "-mcpu=cortex-m33 -mthumb -mfloat-abi=soft"
toolchain m0plus "-mcpu=cortex-m0plus -mthumb -mfloat-abi=soft"

cmake -S "$src" -B "$work/lib" -DCMAKE_TOOLCHAIN_FILE="$work/m33.cmake" -DCMAKE_BUILD_TYPE=MinSizeRel \
  > "$work/lib.log" 2>&1 || { cat "$work/lib.log"; fail "configure of the library for the M33"; }
cmake --build "$work/lib" --target haloplot_core -j2 >> "$work/lib.log" 2>&1 ||
  { cat "$work/lib.log"; fail "build of the library for the M33"; }
cmake --install "$work/lib" --prefix "$work/prefix" > /dev/null
grep -q 'set(haloplot_BUILT_FOR "cortex-m33 (armv8-m.main thumb, hard float)")' \
  "$work/prefix/lib/cmake/haloplot/haloplotConfig.cmake" || fail "the package does not record the M33"

consumer() {  # consumer NAME TOOLCHAIN [ARGS...]: configure the cross consumer; its log in NAME.log
  local name=$1 chain=$2
  shift 2
  cmake -S "$src/tests/package/cross_consumer" -B "$work/$name" -DCMAKE_TOOLCHAIN_FILE="$work/$chain.cmake" \
    -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_BUILD_TYPE=MinSizeRel "$@" > "$work/$name.log" 2>&1
}
# The log's text with CMake's line wrapping undone.
flat() { tr -s ' \n' ' ' < "$work/$1.log"; }
if consumer m0plus m0plus; then cat "$work/m0plus.log"; fail "an M0+ consumer configured against the M33 package"; fi
flat m0plus | grep -q "built for cortex-m33 (armv8-m.main thumb, hard float), but this project compiles for cortex-m0plus (armv6-m thumb, soft float)" ||
  { cat "$work/m0plus.log"; fail "the refusal does not name both CPUs"; }
echo "M0+ consumer refused: $(flat m0plus | grep -o 'haloplotConfig.cmake, version: [^)]*)[^)]*)')"
if consumer m33soft m33soft; then cat "$work/m33soft.log"; fail "a soft-float M33 consumer configured against the hard-float package"; fi
flat m33soft | grep -q "built for cortex-m33 (armv8-m.main thumb, hard float), but this project compiles for cortex-m33 (armv8-m.main thumb, soft float)" ||
  { cat "$work/m33soft.log"; fail "the refusal does not name both float ABIs"; }
echo "M33 soft-float consumer refused"
consumer m33 m33 || { cat "$work/m33.log"; fail "the M33 consumer did not configure"; }
cmake --build "$work/m33" > "$work/m33-build.log" 2>&1 || { cat "$work/m33-build.log"; fail "the M33 consumer did not build"; }
arm-none-eabi-readelf -A "$work/m33/image" | grep -q "Tag_CPU_arch: v8-M.mainline" ||
  fail "the M33 consumer's image is not ARMv8-M"
echo "M33 consumer configured, built and linked (v8-M.mainline)"
consumer m0plus-any m0plus -DHALOPLOT_ACCEPT_ANY_TARGET=ON || { cat "$work/m0plus-any.log"; fail "HALOPLOT_ACCEPT_ANY_TARGET"; }
# The stack of every plotting entry on the M33 against docs/porting.md's figures.
source "$src/tests/firmware/stack_probe.sh"
stack_probe "$src" "$work/prefix" "$work/m33.cmake" M33 "$work" || exit 1
echo "target_check: passed"
