#!/usr/bin/env bash
# The library built for the user's own CPU with the user's own toolchain file: no board, no
# project preset. Writes a minimal arm-none-eabi toolchain file for a Cortex-M0+ (soft float,
# ARMv6-M: a CPU none of the project's boards has), configures the repository with it in a
# scratch build folder and builds haloplot::core and haloplot::hal. Checks that the library was
# built for that CPU, that the package holds both targets, that the controller images (firmware/, which need a board) were left out,
# that the configure names that CPU, and that the build ran the core's float gate, which must
# refuse the same core with one double function added (__aeabi_dmul: soft float); and the stack
# each plotting entry takes on the M0+, against docs/porting.md (tests/firmware/stack_probe.sh).
# Usage: own_toolchain_test.sh SOURCE_DIR
set -euo pipefail
src=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cat > "$work/cortex-m0plus.cmake" <<'TOOLCHAIN'
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR arm)
set(CMAKE_C_COMPILER arm-none-eabi-gcc)
set(CMAKE_CXX_COMPILER arm-none-eabi-g++)
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)
set(CMAKE_C_FLAGS_INIT "-mcpu=cortex-m0plus -mthumb -mfloat-abi=soft")
set(CMAKE_CXX_FLAGS_INIT "-mcpu=cortex-m0plus -mthumb -mfloat-abi=soft")
TOOLCHAIN
cmake -S "$src" -B "$work/build" -DCMAKE_TOOLCHAIN_FILE="$work/cortex-m0plus.cmake" \
  -DCMAKE_BUILD_TYPE=MinSizeRel > "$work/configure.log" 2>&1 ||
  { cat "$work/configure.log"; echo "FAILED: configure with the user's toolchain file"; exit 1; }
grep -q "HALOPLOT_FIRMWARE:BOOL=OFF" "$work/build/CMakeCache.txt" ||
  { echo "FAILED: HALOPLOT_FIRMWARE is not OFF without a board"; exit 1; }
[ ! -e "$work/build/firmware" ] || { echo "FAILED: the controller images were configured"; exit 1; }
# The default build is the library alone (haloplot::hal is header-only: the install shows it).
cmake --build "$work/build" -j2 > "$work/build.log" 2>&1 ||
  { cat "$work/build.log"; echo "FAILED: build of the library"; exit 1; }
cmake --install "$work/build" --prefix "$work/prefix" > "$work/install.log" ||
  { cat "$work/install.log"; echo "FAILED: install"; exit 1; }
targets=$(cat "$work"/prefix/lib/cmake/haloplot/haloplotTargets*.cmake)
for t in haloplot::core haloplot::hal; do
  grep -q "add_library($t " <<<"$targets" || { echo "FAILED: the package has no $t"; exit 1; }
done
[ -f "$work/prefix/include/haloplot/hal/plotter_hal.h" ] ||
  { echo "FAILED: the HAL's headers were not installed"; exit 1; }
lib="$work/build/core/libhaloplot_core.a"
[ -f "$lib" ] || { echo "FAILED: no $lib"; exit 1; }
# Every object for the M0+ (ARMv6-M), none for another CPU.
attrs=$(arm-none-eabi-readelf -A "$lib")
n_objects=$(grep -c "^File:" <<<"$attrs")
n_v6m=$(grep -c "Tag_CPU_arch: v6S-M" <<<"$attrs" || true)
[ "$n_objects" -gt 0 ] && [ "$n_v6m" -eq "$n_objects" ] ||
  { echo "FAILED: $n_v6m of $n_objects objects are ARMv6-M"; exit 1; }
grep -q "float gate passed" "$work/build.log" || { echo "FAILED: the float gate did not run"; exit 1; }
# The configure names the CPU it builds for, as the package records it.
grep -q "haloplot core target: cortex-m0plus (armv6-m thumb, soft float)" "$work/configure.log" ||
  { grep "core target" "$work/configure.log"; echo "FAILED: the configure does not name the M0+"; exit 1; }
# The gate on this soft-float build: the core with one double function added must fail it.
source "$src/tests/rules/float_gate_plant.sh"
float_gate_plant "$src" "$work/build" || exit 1
# The stack of every plotting entry on the M0+ against docs/porting.md's figures.
source "$src/tests/firmware/stack_probe.sh"
stack_probe "$src" "$work/prefix" "$work/cortex-m0plus.cmake" M0+ "$work" || exit 1
echo "own toolchain: libhaloplot_core.a for the Cortex-M0+, $n_objects objects, $(wc -c < "$lib") bytes"
