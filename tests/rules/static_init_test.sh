#!/usr/bin/env bash
# No hidden start-up duty: every object of tests/rules/static_init_check.cpp (the motion runner,
# the band conductor, a job's spec and prepared job, CUT's and DRAW's records, ...) must be
# constant-initialised, so a start-up that runs no static constructors gets it right:
#   - the host compiler builds the file, each object marked __constinit (clang:
#     require_constant_initialization), and refuses it with -DPLANT_CONSTINIT (a runner whose
#     time scale only a constructor sets, as MotionRunner's was);
#   - for the Cortex-M0+ and RV32IMAC (when their compilers are installed) the object file has
#     no .init_array, and the motion runners and the band conductor are all zero bytes, in .bss
#     (no .data copy either);
#     with -DPLANT_CONSTRUCTOR (the same runner without __constinit) the .init_array check must
#     fail.
# The runtime side: the example firmware's start-up runs no constructors and plots through the
# runner under QEMU (the CTest `examples`).
# Usage: static_init_test.sh SOURCE_DIR HOST_CXX
set -uo pipefail
src=$1 cxx=$2
check="$src/tests/rules/static_init_check.cpp"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail=0
bad() { echo "FAILED: $*"; fail=1; }
flags=(-std=c++17 -Wall -Wextra -Werror -I "$src/core/include" -I "$src/hal/include")

"$cxx" "${flags[@]}" -fsyntax-only "$check" || bad "the objects are not all constant-initialised ($cxx)"
if "$cxx" "${flags[@]}" -DPLANT_CONSTINIT -fsyntax-only "$check" > "$work/plant.out" 2>&1; then
  bad "the host compiler took a planted object that needs a constructor"
elif grep -q "constant init" "$work/plant.out"; then
  echo "host ($cxx): all constant-initialised; the planted runner refused: no constant initializer"
else
  cat "$work/plant.out"; bad "the planted object failed to compile for another reason"
fi

# sections OBJ NM SIZE: no .init_array, the runners and the conductor in .bss; prints what is
# in .data.
sections() {
  local obj=$1 nm=$2 size=$3 ok=0 init var
  init=$("$size" -A "$obj" | awk '$1 ~ /^\.init_array/ && $2 > 0 {print $1 " " $2}')
  [ -z "$init" ] || { echo "  .init_array: $init (a constructor to run at start-up)"; ok=1; }
  for var in runner traced_runner conductor; do
    "$nm" "$obj" | grep -q " [bB] $var\$" || { echo "  $var is not in .bss: $("$nm" "$obj" | grep " $var\$")"; ok=1; }
  done
  return $ok
}
cross() {  # cross NAME PREFIX FLAGS...
  local name=$1 prefix=$2
  shift 2
  if ! command -v "${prefix}g++" > /dev/null; then
    echo "$name: ${prefix}g++ not installed, skipped"
    return
  fi
  local cc=("${prefix}g++" "${flags[@]}" "$@" -Os -ffreestanding -fno-exceptions -fno-rtti -fdata-sections -c)
  "${cc[@]}" "$check" -o "$work/$name.o" || { bad "$name: does not compile"; return; }
  if sections "$work/$name.o" "${prefix}nm" "${prefix}size" > "$work/$name.sections"; then
    local data bytes
    bytes=$("${prefix}nm" -S "$work/$name.o" | awk '$4 == "runner" {print $2}')
    data=$("${prefix}size" -A "$work/$name.o" | awk '$1 ~ /^\.(s?data)\./ && $2 > 0 {sub(/^\.s?data\./, "", $1); printf "%s %s, ", $1, $2}')
    echo "$name: no .init_array; runners and conductor in .bss (runner $((16#$bytes)) bytes); constants in .data: ${data%, }"
  else
    cat "$work/$name.sections"; bad "$name: static storage needs start-up work"
  fi
  "${cc[@]}" -DPLANT_CONSTRUCTOR "$check" -o "$work/$name.plant.o" || { bad "$name: the planted file does not compile"; return; }
  if sections "$work/$name.plant.o" "${prefix}nm" "${prefix}size" > "$work/$name.plant.sections"; then
    bad "$name: the section check passed an object with a static constructor"
  else
    echo "$name: planted constructor caught:$(tr -s ' \n' ' ' < "$work/$name.plant.sections")"
  fi
}
cross cortex-m0plus arm-none-eabi- -mcpu=cortex-m0plus -mthumb -mfloat-abi=soft
cross rv32imac riscv64-unknown-elf- -march=rv32imac -mabi=ilp32
[ "$fail" -eq 0 ] && echo "static_init: passed"
exit "$fail"
