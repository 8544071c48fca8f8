# Fails when an Arm object or library holds a floating-point instruction: any VFP, NEON or MVE
# mnemonic (they all begin with "v": vldr, vstr, vpush, vmov, vadd, vmrs, ...) or a coprocessor
# instruction on the FPU's coprocessors p10/p11 (how a disassembler without the FP arch prints
# them). The core has no floating point, but a compiler may still move plain structs through the
# FPU's registers; such code faults on a chip whose FPU is still off, as it is at reset.
# Usage: cmake -DOBJDUMP=arm-none-eabi-objdump -DLIB=libhaloplot_core.a -P check_no_fpu.cmake
if(NOT OBJDUMP OR NOT LIB)
  message(FATAL_ERROR "usage: cmake -DOBJDUMP=<objdump> -DLIB=<library or object> -P check_no_fpu.cmake")
endif()
execute_process(COMMAND ${OBJDUMP} -d ${LIB} OUTPUT_VARIABLE text RESULT_VARIABLE rc
                ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${OBJDUMP} -d failed on ${LIB}: ${err}")
endif()
if(NOT text MATCHES "\n +[0-9a-f]+:\t")
  message(FATAL_ERROR "no instructions disassembled from ${LIB}: nothing was checked")
endif()
# An instruction line is "  addr:<tab>bytes<tab>mnemonic<tab>operands".
set(line "\n +[0-9a-f]+:\t[0-9a-f ]+\t")
string(REGEX MATCHALL "${line}(v[a-z][a-z0-9.]*|(cdp|ldc|stc|mcr|mrc|mcrr|mrrc)2?l?[a-z]*\tp1[01],)[^\n]*"
       found "${text}")
list(LENGTH found n)
if(n GREATER 0)
  list(SUBLIST found 0 12 shown)
  string(REPLACE ";" "" shown "${shown}")
  message(FATAL_ERROR "${n} floating-point instructions in ${LIB}, for example:${shown}")
endif()
message(STATUS "FPU gate passed: no floating-point instruction in ${LIB}")
