#!/usr/bin/env bash
# The examples (examples/), built as a user builds them: against the installed package, with
# the user's own toolchain file (written here; not cmake/arm-none-eabi.cmake).
#   host_plot: built against the host package (BUILD_DIR installed) and run; its haloed spans
#     are `haloplot plot --spans` of the same scene, line for line, and its visible hidden-line
#     pieces as many as `haloplot plot --mode hidden-removed` draws of the same cubes.
#   firmware: the library configured with the toolchain file and no board, built, installed;
#     the example built against that package; twice: hard-float ABI (-mfloat-abi=hard
#     -mfpu=fpv4-sp-d16, the FPU left off at reset) and soft float. Each image runs under QEMU
#     (mps2-an386, a Cortex-M4) and its step trace must equal `haloplot sim` of the example's
#     job.job byte for byte. The example's start-up runs no static constructors: the image
#     must have no .init_array entry, and the motion runner must be in .bss.
#   the stack each plotting entry takes on the M4F (the hard-float library), against
#     docs/porting.md (tests/firmware/stack_probe.sh).
# Usage: examples_test.sh SOURCE_DIR BUILD_DIR HALOPLOT_TOOL
set -euo pipefail
src=$1 build=$2 tool=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAILED: $*"; exit 1; }
quiet() {  # quiet LOG COMMAND...: the command's output in LOG, shown if it fails
  local log=$1
  shift
  "$@" > "$log" 2>&1 || { cat "$log"; fail "$*"; }
}

# The host example.
quiet "$work/install.log" cmake --install "$build" --prefix "$work/host"
quiet "$work/host_plot.log" cmake -S "$src/examples/host_plot" -B "$work/host_plot" \
  -DCMAKE_PREFIX_PATH="$work/host" -DCMAKE_BUILD_TYPE=Release
quiet "$work/host_plot.log" cmake --build "$work/host_plot"
"$work/host_plot/host_plot" > "$work/host_plot.out" || fail "host_plot exit status $?"
cd "$work"
"$tool" demo-scene --cubes 2 -o cubes.edges
"$tool" plot cubes.edges --halo 50 -o cubes.svg --spans cubes.spans --stats 2> cubes.stats
grep '^s ' cubes.spans | sort > want.spans
grep '^s ' host_plot.out | sort > got.spans
[ -s want.spans ] && cmp -s want.spans got.spans ||
  fail "host_plot's spans ($(wc -l < got.spans)) are not haloplot plot's ($(wc -l < want.spans))"
crossings=$(sed -n 's/^crossings=//p' cubes.stats)
grep -qx "haloed: 48 edges, $crossings crossings, $(wc -l < want.spans) spans" host_plot.out ||
  fail "host_plot's counts: $(grep '^haloed' host_plot.out), haloplot plot: $crossings crossings"
"$tool" demo-scene --cubes 2 -o cubes.obj
"$tool" plot cubes.obj --view 30,40 --mode hidden-removed -o solid.svg --spans solid.spans \
  --stats 2> solid.stats
visible=$(grep -c '^s .* 0$' solid.spans)
crossings=$(sed -n 's/^crossings=//p' solid.stats)
hidden_line=$(grep '^hidden lines' host_plot.out)
[[ "$hidden_line" =~ ^"hidden lines: 48 edges, $crossings crossings, $visible visible pieces, "[1-9][0-9]*" hidden pieces"$ ]] ||
  fail "host_plot: '$hidden_line'; haloplot plot: $crossings crossings, $visible visible pieces"
echo "host_plot: $(grep '^haloed' host_plot.out); $hidden_line"

# The firmware example's job on the host.
cp "$src/examples/firmware/job.job" job.job
"$tool" sim job.job -o host.trace
[ -s host.trace ] || fail "haloplot sim wrote no trace"

for abi in hard soft; do
  float="-mfloat-abi=soft"
  [ "$abi" = hard ] && float="-mfloat-abi=hard -mfpu=fpv4-sp-d16"
  cat > "$abi.cmake" <<TOOLCHAIN
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR arm)
set(CMAKE_C_COMPILER arm-none-eabi-gcc)
set(CMAKE_CXX_COMPILER arm-none-eabi-g++)
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)
set(CMAKE_C_FLAGS_INIT "-mcpu=cortex-m4 -mthumb $float -ffunction-sections -fdata-sections")
set(CMAKE_CXX_FLAGS_INIT "-mcpu=cortex-m4 -mthumb $float -ffunction-sections -fdata-sections")
TOOLCHAIN
  # The library: no board, the core alone (haloplot::hal is header-only), installed.
  quiet "lib-$abi.log" cmake -S "$src" -B "lib-$abi" -DCMAKE_TOOLCHAIN_FILE="$work/$abi.cmake" \
    -DCMAKE_BUILD_TYPE=MinSizeRel
  quiet "lib-$abi.log" cmake --build "lib-$abi" --target haloplot_core -j2
  grep -q "float gate passed" "lib-$abi.log" || fail "$abi: the core's FPU gate did not run"
  quiet "install-$abi.log" cmake --install "lib-$abi" --prefix "$work/prefix-$abi"
  # The example against it.
  quiet "fw-$abi.log" cmake -S "$src/examples/firmware" -B "fw-$abi" \
    -DCMAKE_TOOLCHAIN_FILE="$work/$abi.cmake" -DCMAKE_PREFIX_PATH="$work/prefix-$abi" \
    -DCMAKE_BUILD_TYPE=MinSizeRel
  quiet "fw-$abi.log" cmake --build "fw-$abi"
  ! grep -q "warning:" "fw-$abi.log" || { cat "fw-$abi.log"; fail "$abi: the example builds with warnings"; }
  image="fw-$abi/example.elf"
  # Built for the ABI asked: hard float passes arguments in VFP registers.
  vfp_args=$(arm-none-eabi-readelf -A "$image" | grep -c "Tag_ABI_VFP_args: VFP registers" || true)
  if [ "$abi" = hard ]; then [ "$vfp_args" -gt 0 ]; else [ "$vfp_args" -eq 0 ]; fi ||
    fail "$abi: the image's float ABI attributes are not the $abi ABI's"
  # Its start-up runs no static constructors: the image must need none. No .init_array entry,
  # and the motion runner constant-initialised to zero bytes (in .bss, not .data).
  init_array=$(arm-none-eabi-size -A "$image" | awk '$1 == ".init_array" {print $2}')
  [ -z "$init_array" ] || [ "$init_array" -eq 0 ] ||
    fail "$abi: the image has $init_array bytes of .init_array, which its start-up does not run"
  arm-none-eabi-nm -C "$image" > "$abi.nm"  # (a file: grep -q would break nm's pipe)
  grep -q " [bB] (anonymous namespace)::motion$" "$abi.nm" ||
    fail "$abi: the motion runner is not in .bss: $(grep '::motion$' "$abi.nm")"
  # No floating-point instruction anywhere in the image (the FPU is never switched on).
  quiet "gate-$abi.log" cmake -DOBJDUMP=arm-none-eabi-objdump -DLIB="$image" \
    -P "$src/cmake/check_no_float.cmake"
  # As the QEMU tests run their images (tests/firmware/qemu_common.sh); the timeout is a
  # backstop for a hung emulator only.
  rc=0
  timeout 600 qemu-system-arm -M mps2-an386 -nographic -monitor none -serial none \
    -semihosting-config enable=on,target=native -icount shift=0,align=off,sleep=off \
    -kernel "$image" > "$abi.out" 2>&1 || rc=$?
  [ "$rc" -eq 0 ] || { cat "$abi.out"; fail "$abi: the image's exit status $rc"; }
  sed -n '/^haloplot-trace 2$/,/^end /p' "$abi.out" > "$abi.trace"
  [ -s "$abi.trace" ] && cmp -s "$abi.trace" host.trace ||
    fail "$abi: the image's trace ($(wc -c < "$abi.trace") bytes) is not haloplot sim's ($(wc -c < host.trace) bytes)"
  grep -qx "example cpacr=0" "$abi.out" || fail "$abi: the FPU was switched on: $(grep cpacr "$abi.out")"
  echo "firmware, $abi float: trace identical to haloplot sim ($(wc -c < host.trace) bytes," \
    "$(sed -n 's/^example step_events=//p' "$abi.out") step events), FPU off," \
    "$(arm-none-eabi-size -A "$image" | awk '/^.text/ {print $2}') bytes of text"
done
# The stack of every plotting entry on the M4F (the hard-float library above) against
# docs/porting.md's figures.
source "$src/tests/firmware/stack_probe.sh"
stack_probe "$src" "$work/prefix-hard" "$work/hard.cmake" M4F "$work" || fail "the M4F stack"
echo "examples: host_plot and the firmware (hard and soft float) pass"
