#!/usr/bin/env bash
# The float gate (cmake/check_no_float.cmake), which every cross build of the core runs after
# linking the library: passes the firmware preset's libhaloplot_core.a (hard float, Cortex-M4F),
# and refuses objects with floating-point instructions, compiled here: a float addition (vadd) and
# 64-bit constants stored as GCC emits them for the M4F (vldr/vstr through a d register), which the
# core's -mgeneral-regs-only must keep out; and refuses the core with one double function added
# (tests/rules/float_gate_plant.sh: software routines, __aeabi_dmul).
# Usage: no_fpu_test.sh SOURCE_DIR FIRMWARE_BUILD_DIR
set -uo pipefail
src=$1 build=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail=0
gate() { cmake -DOBJDUMP=arm-none-eabi-objdump -DLIB="$1" -P "$src/cmake/check_no_float.cmake" 2>&1; }
lib="$build/core/libhaloplot_core.a"
if [ ! -f "$lib" ]; then
  echo "FAILED: $lib is missing: build the firmware preset first (cmake --build --preset firmware)"
  exit 1
fi
if out=$(gate "$lib"); then echo "$out"; else echo "$out"; echo "FAILED: the core holds FPU instructions"; fail=1; fi
m4f=(-mcpu=cortex-m4 -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16 -O2)
printf 'float add(float a, float b) { return a + b; }\n' > "$work/add.c"
printf 'void put(long long* p) { p[2] = 0x123456789abcdefLL; p[3] = 0x1122334455667788LL; }\n' > "$work/copy.c"
for f in add copy; do
  arm-none-eabi-gcc "${m4f[@]}" -c "$work/$f.c" -o "$work/$f.o"
  if gate "$work/$f.o" > "$work/$f.out"; then
    echo "FAILED: the gate passed $f.c, which uses the FPU:"; arm-none-eabi-objdump -d "$work/$f.o"
    fail=1
  else
    echo "refused $f.c: $(grep -m1 'floating-point instructions' "$work/$f.out" | sed 's/^ *//')"
  fi
  # The same code built as the core is: no FPU instruction is left.
  arm-none-eabi-gcc "${m4f[@]}" -mgeneral-regs-only -c "$work/$f.c" -o "$work/$f.gr.o" 2> /dev/null &&
    { gate "$work/$f.gr.o" > /dev/null || { echo "FAILED: $f.c with -mgeneral-regs-only"; fail=1; }; }
done
# The whole gate (instructions and software routines) on this build's core with one double
# function planted in it: the M4F's FPU is single precision, so a double is a routine call.
source "$src/tests/rules/float_gate_plant.sh"
float_gate_plant "$src" "$build" || fail=1
[ "$fail" -eq 0 ] && echo "core_no_fpu: passed"
exit "$fail"
