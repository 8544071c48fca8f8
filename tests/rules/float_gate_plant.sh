#!/usr/bin/env bash
# The floating-point gate (cmake/check_no_float.cmake) on one cross build of the core, and on
# its bad case: passes the build's libhaloplot_core.a, then compiles planted_double.cpp (one
# function that computes in double) with the exact command the build compiled a core source
# with (compile_commands.json), adds it to a copy of the library and runs the same gate on the
# copy, which must fail and name the floating point it found. Where the core's own flags refuse
# the double at compile time (Arm hard float: -mgeneral-regs-only), that is said, and the
# planted object is compiled without that flag, as an integrator's build that dropped it would.
# Sourced by the tests that build a core (own_toolchain: the M0+; core_no_fpu: the M4F;
# riscv_qemu: RV32IMAC), or run: float_gate_plant.sh SOURCE_DIR BUILD_DIR
# Prints one line "float gate: ..." and returns non-zero when a check fails.
float_gate_plant() {
  local src=$1 build=$2 scratch
  scratch=$(mktemp -d)
  local lib="$build/core/libhaloplot_core.a"
  cache() { sed -n "s/^$1:[A-Z]*=//p" "$build/CMakeCache.txt"; }
  local objdump nm ar
  objdump=$(cache CMAKE_OBJDUMP)  # its siblings: the toolchain file may set them uncached
  nm=${objdump%objdump}nm ar=${objdump%objdump}ar
  gate() { cmake -DOBJDUMP="$objdump" -DNM="$nm" -DLIB="$1" -P "$src/cmake/check_no_float.cmake" 2>&1; }
  if ! gate "$lib" > "$scratch/good.out"; then
    cat "$scratch/good.out"; echo "FAILED: the float gate refuses the core itself ($lib)"
    rm -rf "$scratch"; return 1
  fi
  # The command that compiled status.cpp, with the planted source and object put in.
  local command
  command=$(grep -o '"command": "[^"]*core/status/status\.cpp"' "$build/compile_commands.json" |
    sed -e 's/^"command": "//' -e 's/"$//')
  [ -n "$command" ] || { echo "FAILED: no compile command for status.cpp in $build"; rm -rf "$scratch"; return 1; }
  local -a argv kept
  read -r -a argv <<< "$command"
  local skip=0 arg refused=""
  for arg in "${argv[@]}"; do
    if [ "$skip" = 1 ]; then skip=0; continue; fi
    case "$arg" in
      -o | -c | -MF | -MT | -MQ) skip=1 ;;
      -MD | -MMD) ;;
      *) kept+=("$arg") ;;
    esac
  done
  if ! (cd "$build" && "${kept[@]}" -c "$src/tests/rules/planted_double.cpp" -o "$scratch/planted.o") \
    > "$scratch/cc.out" 2>&1; then
    if grep -q -- "-mgeneral-regs-only" <<< "$command" && grep -q "not permitted with '-mgeneral-regs-only'" "$scratch/cc.out"; then
      refused="the core's own flags refuse it at compile time, -mgeneral-regs-only; built without: "
      local -a plain=()
      for arg in "${kept[@]}"; do [ "$arg" = -mgeneral-regs-only ] || plain+=("$arg"); done
      (cd "$build" && "${plain[@]}" -c "$src/tests/rules/planted_double.cpp" -o "$scratch/planted.o") ||
        { echo "FAILED: the planted source does not compile"; rm -rf "$scratch"; return 1; }
    else
      cat "$scratch/cc.out"; echo "FAILED: the planted source does not compile with the core's flags"
      rm -rf "$scratch"; return 1
    fi
  fi
  cp "$lib" "$scratch/planted.a"
  "$ar" r "$scratch/planted.a" "$scratch/planted.o"
  if gate "$scratch/planted.a" > "$scratch/bad.out"; then
    cat "$scratch/bad.out"; echo "FAILED: the float gate passed a core holding a double function"
    rm -rf "$scratch"; return 1
  fi
  local named
  named=$(sed -n 's/^ *software floating-point routines: //p' "$scratch/bad.out")
  if [ -z "$named" ]; then
    cat "$scratch/bad.out"; echo "FAILED: the float gate refused the planted core without naming a routine"
    rm -rf "$scratch"; return 1
  fi
  echo "float gate: passes the core; refuses it with one double function added (${refused}names $named)"
  rm -rf "$scratch"
}
if [ "${BASH_SOURCE[0]}" = "$0" ]; then
  set -uo pipefail
  float_gate_plant "$1" "$2"
fi
