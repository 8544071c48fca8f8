# The floating-point gate: fails when a library, object or image holds floating point in either
# form, on Arm or RISC-V, hard or soft float:
#   - an instruction: on Arm any VFP, NEON or MVE mnemonic (they all begin with "v": vldr, vstr,
#     vpush, vmov, vadd, vmrs, ...) or a coprocessor instruction on the FPU's coprocessors
#     p10/p11 (how a disassembler without the FP arch prints them); on RISC-V any F, D, Q, Zfh or
#     Zfinx instruction (they all begin with "f": flw, fsd, fadd.d, fcvt.w.s, fmv.x.w, frcsr,
#     ...; fence is not one of them);
#   - a software floating-point routine or math function in the symbol table, defined or
#     referenced (cmake/float_routines.cmake: __aeabi_dmul, __aeabi_fadd, __muldf3, __addsf3,
#     __floatsidf, sqrt, ...): what a soft-float build (the M0+, a Cortex-M3, RV32IMAC) or a
#     hard-float build with a single-precision FPU (doubles on the M4F) calls instead.
# The core has no floating point, but a compiler may still move plain structs through the FPU's
# registers; such code faults on a chip whose FPU is still off, as it is at reset.
# Usage: cmake -DOBJDUMP=<objdump> [-DNM=<nm>] -DLIB=<library, object or image>
#              -P check_no_float.cmake
# (NM defaults to the objdump's sibling: arm-none-eabi-objdump -> arm-none-eabi-nm.)
if(NOT OBJDUMP OR NOT LIB)
  message(FATAL_ERROR "usage: cmake -DOBJDUMP=<objdump> [-DNM=<nm>] -DLIB=<library or object> "
                      "-P check_no_float.cmake")
endif()
if(NOT NM)
  string(REGEX REPLACE "objdump$" "nm" NM "${OBJDUMP}")
endif()
include(${CMAKE_CURRENT_LIST_DIR}/float_routines.cmake)

execute_process(COMMAND ${OBJDUMP} -d ${LIB} OUTPUT_VARIABLE text RESULT_VARIABLE rc
                ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${OBJDUMP} -d failed on ${LIB}: ${err}")
endif()
if(NOT text MATCHES "\n *[0-9a-f]+:\t")
  message(FATAL_ERROR "no instructions disassembled from ${LIB}: nothing was checked")
endif()
# An instruction line is "  addr:<tab>bytes<tab>mnemonic<tab>operands".
set(line "\n *[0-9a-f]+:\t[0-9a-f ]+\t")
if(text MATCHES "file format elf[0-9]*-(little|big)arm")
  set(isa Arm)
  string(REGEX MATCHALL "${line}(v[a-z][a-z0-9.]*|(cdp|ldc|stc|mcr|mrc|mcrr|mrrc)2?l?[a-z]*\tp1[01],)[^\n]*"
         found "${text}")
elseif(text MATCHES "file format elf[0-9]*-(little|big)riscv")
  set(isa RISC-V)
  string(REGEX MATCHALL "${line}f[a-z][a-z0-9.]*[^\n]*" found "${text}")
  list(FILTER found EXCLUDE REGEX "\tfence")
else()
  # Another CPU: its instructions are not known here, its symbols are still checked.
  string(REGEX MATCH "file format [^\n]*" format "${text}")
  set(isa "${format}: symbols only, instructions not checked")
  set(found "")
endif()
set(problems "")
list(LENGTH found n)
if(n GREATER 0)
  list(SUBLIST found 0 12 shown)
  string(REPLACE ";" "" shown "${shown}")
  string(APPEND problems "${n} floating-point instructions, for example:${shown}\n")
endif()

execute_process(COMMAND ${NM} ${LIB} OUTPUT_VARIABLE symbols RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${NM} failed on ${LIB}: ${err}")
endif()
string(REPLACE "\n" ";" lines "${symbols}")
set(routines "")
foreach(entry IN LISTS lines)
  if(entry MATCHES " [A-Za-z] (${HALOPLOT_FLOAT_ROUTINES})$")
    list(APPEND routines ${CMAKE_MATCH_1})
  endif()
endforeach()
if(routines)
  list(REMOVE_DUPLICATES routines)
  list(SORT routines)
  string(REPLACE ";" " " routines "${routines}")
  string(APPEND problems "software floating-point routines: ${routines}\n")
endif()
if(problems)
  message(FATAL_ERROR "floating point in ${LIB} (${isa}):\n${problems}")
endif()
message(STATUS "float gate passed (${isa}): no floating-point instruction or routine in ${LIB}")
