#!/usr/bin/env bash
# Lean links (firmware/lean/lean_link.cpp): what an edges-only banded plot costs an image.
# For each firmware build given (the firmware preset's, and the firmware-mps2 preset's when it
# has been built):
#   - the solid-stage gate (firmware/check_no_solid.cmake) passes fw_lean_bands, the haloed plot
#     in bands, and refuses fw_lean_solid_bands, a solid in bands, naming begin_solid: the gate
#     sees the solid objects when they are there;
#   - fw_lean_bands' .text is at most 1.3 times fw_lean_haloed's, the same plot unbanded
#     through job_prepare (both through the planner, step prep and step tick).
# Usage: lean_link_test.sh SOURCE_DIR FIRMWARE_BUILD_DIR [MORE_FIRMWARE_BUILD_DIRS...]
set -uo pipefail
src=$1
shift
fail=0
gate() {  # BUILD IMAGE
  cmake -DNM=arm-none-eabi-nm -DLIB="$1/core/libhaloplot_core.a" -DIMAGE="$1/firmware/$2.elf" \
    -DMEMBERS="$(cat "$1/firmware/solid_objects.txt")" -P "$src/firmware/check_no_solid.cmake" 2>&1
}
text() { arm-none-eabi-size -A "$1" | awk '$1 == ".text" { print $2 }'; }
first=1
for build in "$@"; do
  if [ ! -f "$build/firmware/fw_lean_bands.elf" ]; then
    if [ "$first" -eq 1 ]; then
      echo "FAILED: no $build/firmware/fw_lean_bands.elf: build the firmware preset first"
      fail=1
    else
      echo "skipped $build: not built"
    fi
    first=0
    continue
  fi
  first=0
  if out=$(gate "$build" fw_lean_bands); then
    echo "$out" | grep -m1 'gate passed'
  else
    echo "$out"
    echo "FAILED: fw_lean_bands (edges in bands) links the solid stages"
    fail=1
  fi
  if out=$(gate "$build" fw_lean_solid_bands); then
    echo "FAILED: the gate passed fw_lean_solid_bands, which plots a solid in bands"
    fail=1
  elif ! echo "$out" | grep -q '_ZN8haloplot13BandConductor11begin_solid'; then
    echo "$out"
    echo "FAILED: the gate refused fw_lean_solid_bands without naming BandConductor::begin_solid"
    fail=1
  else
    echo "refused fw_lean_solid_bands: $(echo "$out" | grep -c '^ *_Z') solid symbols"
  fi
  haloed=$(text "$build/firmware/fw_lean_haloed.elf")
  bands=$(text "$build/firmware/fw_lean_bands.elf")
  solid=$(text "$build/firmware/fw_lean_solid_bands.elf")
  echo ".text: haloed $haloed, haloed in bands $bands, solid in bands $solid bytes ($build)"
  if [ $((bands * 10)) -gt $((haloed * 13)) ]; then
    echo "FAILED: the banded edge plot is more than 1.3 times the unbanded one"
    fail=1
  fi
done
[ "$fail" -eq 0 ] && echo "lean_link: passed"
exit "$fail"
