#!/usr/bin/env bash
# RISC-V as a target: the core built for RV32IMAC with the repository's toolchain file
# (cmake/rv32imac.cmake: no board, the library alone) and installed; the RV32 test image
# (tests/firmware/riscv) built against that package and booted under qemu-system-riscv32
# (`virt`, semihosting, -icount: qemu_common.sh's command line, as the Arm images boot). Checks
#   - the configure names the target (rv32imac, ABI ilp32), and says nothing of Arm;
#   - the library's and the image's float gates pass (no F/D instruction, no __muldf3 and
#     friends), and the gate refuses the same core with one double function added
#     (tests/rules/float_gate_plant.sh);
#   - the image is RV32 (ELF32, RISC-V, the soft-float ABI) and exits 0;
#   - its haloed spans of 4 x 4 cubes (halo 50) equal `haloplot plot --spans` of the same
#     scene on the host, line for line, and its crossing count the host's;
#   - every size query on the test scenes at least what its run used, at most 1.5 times it
#     (rv32_sizes.elf: tests/unit/size_bound_checks.h, as CTest size_bounds runs it on the host);
#   - the stack each plotting entry takes on RV32, against docs/porting.md
#     (tests/firmware/stack_probe.sh).
# Usage: qemu_riscv_test.sh SOURCE_DIR HALOPLOT_TOOL
src=$1
export HALOPLOT_QEMU_MACHINE=virt
source "$(dirname "$0")/qemu_common.sh" riscv_qemu "" "$2"
source "$src/tests/rules/float_gate_plant.sh"
objdump=riscv64-unknown-elf-objdump
# quiet LOG COMMAND...: the command's output in LOG, shown if it fails.
quiet() {
  local log=$1
  shift
  "$@" > "$log" 2>&1 || { cat "$log"; bad "$*"; finish; exit 1; }
}

quiet "$work/lib.log" cmake -S "$src" -B "$work/lib" -DCMAKE_TOOLCHAIN_FILE="$src/cmake/rv32imac.cmake" \
  -DCMAKE_BUILD_TYPE=MinSizeRel
if grep -q "haloplot core target: rv32imac (rv32imac, ABI ilp32)" "$work/lib.log" &&
  ! grep -q "HALOPLOT_TARGET_ARM" "$work/lib.log"; then
  ok
else
  bad "the configure's target lines: $(grep -i "target" "$work/lib.log")"
fi
quiet "$work/lib-build.log" cmake --build "$work/lib" -j2
if grep -q "float gate passed (RISC-V)" "$work/lib-build.log"; then ok; else bad "the core's float gate did not run"; fi
if float_gate_plant "$src" "$work/lib"; then ok; else bad "the float gate on RV32"; fi
quiet "$work/install.log" cmake --install "$work/lib" --prefix "$work/prefix"

quiet "$work/image.log" cmake -S "$src/tests/firmware/riscv" -B "$work/image" \
  -DCMAKE_TOOLCHAIN_FILE="$src/cmake/rv32imac.cmake" -DCMAKE_PREFIX_PATH="$work/prefix" \
  -DHALOPLOT_SOURCE_DIR="$src" -DCMAKE_BUILD_TYPE=MinSizeRel
quiet "$work/image-build.log" cmake --build "$work/image"
image="$work/image/rv32_spans.elf"
header=$(riscv64-unknown-elf-readelf -h "$image")
if grep -q "Class: *ELF32" <<< "$header" && grep -q "Machine: *RISC-V" <<< "$header" &&
  grep -q "Flags: .*RVC, soft-float ABI" <<< "$header"; then
  ok
else
  bad "the image is not RV32 with the soft-float ABI: $(grep -E "Class|Machine|Flags" <<< "$header")"
fi
if cmake -DOBJDUMP="$objdump" -DLIB="$image" -P "$src/cmake/check_no_float.cmake" > "$work/gate.log" 2>&1; then
  ok
else
  cat "$work/gate.log"; bad "the image's float gate"
fi

qemu "$image" > "$work/fw.out"
rc=$?
if [ "$rc" -eq 0 ]; then ok; else bad "the RV32 image's exit status $rc: $(grep -E "FAILED|trap" "$work/fw.out")"; fi
grep '^fw ' "$work/fw.out"

cd "$work"
"$tool" demo-scene --cubes 4 -o scene.edges
"$tool" plot scene.edges --halo 50 -o scene.svg --spans scene.spans --stats 2> scene.stats
grep '^s ' scene.spans | sort > want.spans
grep '^s ' fw.out | sort > got.spans
if [ -s want.spans ] && cmp -s want.spans got.spans; then
  ok
  echo "spans identical: $(wc -l < want.spans) haloed spans of 4 x 4 cubes"
else
  bad "the RV32 image's spans ($(wc -l < got.spans)) are not haloplot plot's ($(wc -l < want.spans)):"
  diff want.spans got.spans | head -5
fi
host_crossings=$(sed -n 's/^crossings=//p' scene.stats)
fw_crossings=$(sed -n 's/^fw crossings=//p' fw.out)
if [ -n "$fw_crossings" ] && [ "$fw_crossings" = "$host_crossings" ]; then ok; else bad "crossings: RV32 $fw_crossings, host $host_crossings"; fi
echo "RV32 image: $(riscv64-unknown-elf-size -A "$image" | awk '/^.text/ {print $2}') bytes of text"
# The size queries against their runs on the chip (tests/unit/size_bound_checks.h).
qemu "$work/image/rv32_sizes.elf" > "$work/sizes.out"
rc=$?
checks=$(grep -c '^fw size ' "$work/sizes.out")
if [ "$rc" -eq 0 ] && [ "$checks" -gt 0 ] && ! grep -q 'FAILED' "$work/sizes.out"; then
  ok
  echo "size queries on RV32: $checks checks, each at least its run's use and at most 1.5 times it"
else
  grep -E '^fw size .*FAILED|trap' "$work/sizes.out"; bad "the size queries on RV32 (exit $rc, $checks checks)"
fi
# The stack of every plotting entry on RV32 against docs/porting.md's figures.
source "$src/tests/firmware/stack_probe.sh"
if stack_probe "$src" "$work/prefix" "$src/cmake/rv32imac.cmake" RV32 "$work"; then ok; else bad "the RV32 stack"; fi
finish
