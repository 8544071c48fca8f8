#!/usr/bin/env bash
# The Cortex-M0+ (ARMv6-M: no 32 x 32 -> 64 multiply; the core builds its products from 16-bit
# halves there, geometry/product.h) computes what the host does: the core built and installed
# for it with a toolchain file of its own, tests/firmware/cpu_bench's images linked against it
# and booted under QEMU's mps2-an386 (whose Cortex-M4 runs ARMv6-M code). Checks
#   - the library's objects are ARMv6-M, and the images hold no ARMv7-M instruction (SMULL,
#     UMULL, SDIV, IT, CBZ and the like, which the emulated M4 would run without a fault);
#   - the haloed spans of 4 x 4 cubes (halo 50) equal `haloplot plot --spans`' line for line,
#     and the crossing count the host's;
#   - CUT on the EDGE rows (tools/bench_cpus.sh's scenes) finds the host's crossings on each.
# Usage: qemu_m0plus_test.sh SOURCE_DIR HALOPLOT_TOOL
src=$1
export HALOPLOT_QEMU_MACHINE=mps2-an386
source "$(dirname "$0")/qemu_common.sh" m0plus_qemu "" "$2"
quiet() {  # quiet LOG COMMAND...: the command's output in LOG, shown if it fails
  local log=$1
  shift
  "$@" > "$log" 2>&1 || { cat "$log"; bad "$*"; finish; exit 1; }
}
cat > "$work/m0plus.cmake" <<'TOOLCHAIN'
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR arm)
set(CMAKE_C_COMPILER arm-none-eabi-gcc)
set(CMAKE_CXX_COMPILER arm-none-eabi-g++)
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)
set(CMAKE_C_FLAGS_INIT "-mcpu=cortex-m0plus -mthumb -mfloat-abi=soft -ffunction-sections -fdata-sections")
set(CMAKE_CXX_FLAGS_INIT "-mcpu=cortex-m0plus -mthumb -mfloat-abi=soft -ffunction-sections -fdata-sections")
TOOLCHAIN
quiet "$work/lib.log" cmake -S "$src" -B "$work/lib" -DCMAKE_TOOLCHAIN_FILE="$work/m0plus.cmake" \
  -DCMAKE_BUILD_TYPE=MinSizeRel
quiet "$work/lib-build.log" cmake --build "$work/lib" --target haloplot_core -j2
quiet "$work/install.log" cmake --install "$work/lib" --prefix "$work/prefix"
quiet "$work/image.log" cmake -S "$src/tests/firmware/cpu_bench" -B "$work/image" \
  -DCMAKE_TOOLCHAIN_FILE="$work/m0plus.cmake" -DCMAKE_PREFIX_PATH="$work/prefix" \
  -DHALOPLOT_SOURCE_DIR="$src" -DCMAKE_BUILD_TYPE=MinSizeRel
quiet "$work/image-build.log" cmake --build "$work/image" -j2
attrs=$(arm-none-eabi-readelf -A "$work/lib/core/libhaloplot_core.a")
if [ "$(grep -c "^File:" <<< "$attrs")" -eq "$(grep -c "Tag_CPU_arch: v6S-M" <<< "$attrs")" ]; then
  ok
else
  bad "the library is not all ARMv6-M objects"
fi
# mps2-an386's Cortex-M4 would run ARMv7-M instructions a real M0+ faults on: none in the images
# (the linker script drops their attributes, so the instructions themselves are looked at).
for image in spans cpu_bench_cut; do
  v7=$(arm-none-eabi-objdump -d "$work/image/$image.elf" | awk -F'\t' '
    $3 ~ /^(smull|umull|smlal|umlal|mla|mls|sdiv|udiv|cbz|cbnz|it[et]*|ldrd|strd)(\.w)?$/ { n++ }
    END { print n + 0 }')
  if [ "$v7" -eq 0 ]; then ok; else bad "$image.elf holds $v7 ARMv7-M instructions"; fi
done

qemu "$work/image/spans.elf" > "$work/fw.out"
rc=$?
if [ "$rc" -eq 0 ]; then ok; else bad "the spans image's exit status $rc: $(grep FAILED "$work/fw.out")"; fi
cd "$work"
"$tool" demo-scene --cubes 4 -o scene.edges
"$tool" plot scene.edges --halo 50 -o scene.svg --spans scene.spans --stats 2> scene.stats
grep '^s ' scene.spans | sort > want.spans
grep '^s ' fw.out | sort > got.spans
if [ -s want.spans ] && cmp -s want.spans got.spans; then
  ok
  echo "spans identical: $(wc -l < want.spans) haloed spans of 4 x 4 cubes"
else
  bad "the M0+'s spans ($(wc -l < got.spans)) are not haloplot plot's ($(wc -l < want.spans)):"
  diff want.spans got.spans | head -5
fi
host_crossings=$(sed -n 's/^crossings=//p' scene.stats)
fw_crossings=$(sed -n 's/^fw crossings=//p' fw.out)
if [ -n "$fw_crossings" ] && [ "$fw_crossings" = "$host_crossings" ]; then ok; else bad "crossings: M0+ $fw_crossings, host $host_crossings"; fi

qemu "$work/image/cpu_bench_cut.elf" > "$work/cut.out"
rc=$?
if [ "$rc" -eq 0 ]; then ok; else bad "the CUT image's exit status $rc"; fi
rows=0
while read -r _ _ n l seed crossings instructions _; do
  length=$(printf '0.%06d' "$l")
  "$tool" random-scene --edges "$n" --length "$length" --seed "$seed" -o "$work/s.edges"
  stats=$("$tool" cut "$work/s.edges" -o "$work/s.cut" --stats 2>&1)
  host=$(( $(sed -n 's/^crossings=//p' <<<"$stats") + $(sed -n 's/^equal_depth=//p' <<<"$stats") ))
  echo "N=$n L=$length seed=$seed: M0+ $crossings crossings in $instructions instructions, host $host"
  if [ "$crossings" = "$host" ]; then ok; else bad "crossings differ"; fi
  rows=$((rows + 1))
done < <(grep '^fw row ' "$work/cut.out")
[ "$rows" -eq 5 ] || bad "expected 5 rows, got $rows"
finish
