# Fails when a linked image holds code of the solid-model stages: any global symbol that one of
# the named library members defines (core/solid, core/surface and the band conductor's solid
# stage, band/solid_band.cpp). Used on the edges-only banded program (firmware/lean): a haloed
# plot in bands runs CUT, DRAW and the path planner only, so none of those objects may be linked.
# Only strong global symbols count (nm types T, D, B, R): a weak inline function or a local
# helper may have the same name in an object that is allowed.
# Usage: cmake -DNM=arm-none-eabi-nm -DLIB=libhaloplot_core.a -DIMAGE=image.elf
#              -DMEMBERS=solid_band.cpp,topology.cpp,... -P check_no_solid.cmake
cmake_minimum_required(VERSION 3.20)  # IN_LIST in script mode
if(NOT NM OR NOT LIB OR NOT IMAGE OR NOT MEMBERS)
  message(FATAL_ERROR "usage: cmake -DNM=<nm> -DLIB=<core library> -DIMAGE=<elf> "
                      "-DMEMBERS=<source names, comma-separated> -P check_no_solid.cmake")
endif()
string(REPLACE "," ";" members "${MEMBERS}")
execute_process(COMMAND ${NM} --defined-only ${LIB} OUTPUT_VARIABLE lib_symbols RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "nm failed on ${LIB}")
endif()
# The archive's listing: a "member.o:" line, then that member's symbols.
string(REPLACE "\n" ";" lib_lines "${lib_symbols}")
set(in_solid FALSE)
set(n_solid 0)
set(seen_members 0)
foreach(line IN LISTS lib_lines)
  if(line MATCHES "^([^ ]+)\\.(o|obj):$")
    set(in_solid FALSE)
    if(CMAKE_MATCH_1 IN_LIST members)
      set(in_solid TRUE)
      math(EXPR seen_members "${seen_members} + 1")
    endif()
  elseif(in_solid AND line MATCHES "^[0-9a-f]+ [TDBR] (.+)$")
    set("solid:${CMAKE_MATCH_1}" TRUE)  # a set of names: one variable each, looked up by name
    math(EXPR n_solid "${n_solid} + 1")
  endif()
endforeach()
list(LENGTH members n_members)
if(NOT seen_members EQUAL n_members OR n_solid EQUAL 0)
  message(FATAL_ERROR "found ${seen_members} of the ${n_members} solid members in ${LIB} "
                      "(${MEMBERS}): nothing would be checked")
endif()
execute_process(COMMAND ${NM} --defined-only ${IMAGE} OUTPUT_VARIABLE image_symbols
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "nm failed on ${IMAGE}")
endif()
string(REPLACE "\n" ";" image_lines "${image_symbols}")
set(bad "")
foreach(line IN LISTS image_lines)
  if(line MATCHES "^[0-9a-f]+ [A-Za-z] (.+)$")
    set(name "${CMAKE_MATCH_1}")
    if(DEFINED "solid:${name}")
      string(APPEND bad "  ${name}\n")
    endif()
  endif()
endforeach()
if(bad)
  message(FATAL_ERROR "${IMAGE} links the solid stages:\n${bad}")
endif()
message(STATUS "lean-link gate passed: none of the ${n_solid} symbols of the ${n_members} solid objects in ${IMAGE}")
