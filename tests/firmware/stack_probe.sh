# The stack stated and guarded (sourced by the tests that build the library for a CPU:
# own_toolchain for the Cortex-M0+, examples for the M4F, package_target for the M33,
# riscv_qemu for RV32IMAC): builds the stack probe (tests/firmware/stack) against that CPU's
# installed package with the same toolchain file, boots it under QEMU (mps2-an386 for Arm code,
# virt for RISC-V; qemu_common.sh's command line) and compares each entry's measured bytes with
# the figure docs/porting.md states for that CPU (the table between the stack-table markers).
# Fails when an entry takes more than its stated figure, or has none; and shows the comparison
# failing on the table with one figure planted 8 bytes below the measurement.
# Usage: source stack_probe.sh; stack_probe SOURCE_DIR PREFIX TOOLCHAIN_FILE CPU SCRATCH
#   CPU: one of the table's columns: M0+ | M4F | M33 | RV32
# Prints "stack CPU: entry=bytes/stated ..." and returns non-zero when a check fails.
source "$(dirname "${BASH_SOURCE[0]}")/qemu_run.sh"

# The stated figure of ENTRY for CPU in TABLE (the markdown table's lines): empty if none.
stack_stated() {
  local table=$1 cpu=$2 entry=$3
  awk -F'|' -v cpu="$cpu" -v entry="$entry" '
    function trim(s) { gsub(/^[ \t`]+|[ \t`]+$/, "", s); return s }
    NR == 1 { for (i = 2; i < NF; ++i) if (trim($i) == cpu) col = i; next }
    col && trim($2) == entry { v = trim($col); gsub(",", "", v); print v }' "$table"
}

# Compares the probe's "fw stack ENTRY=BYTES" lines in OUT with TABLE's CPU column; prints the
# figures, returns non-zero on an entry over its figure or without one.
stack_compare() {
  local out=$1 table=$2 cpu=$3 bad=0 line entry bytes stated summary=""
  while IFS= read -r line; do
    entry=${line#fw stack }
    bytes=${entry##*=}
    entry=${entry%=*}
    stated=$(stack_stated "$table" "$cpu" "$entry")
    if [ -z "$stated" ]; then
      echo "  $entry: $bytes bytes, no figure stated for $cpu"; bad=1
    elif [ "$bytes" -gt "$stated" ]; then
      echo "  $entry: $bytes bytes, more than the stated $stated for $cpu"; bad=1
    fi
    summary+=" $entry=$bytes/$stated"
  done < <(grep '^fw stack ' "$out")
  [ -n "$summary" ] || { echo "  no figures measured"; bad=1; }
  echo "stack $cpu (measured/stated):$summary"
  return $bad
}

stack_probe() {
  local src=$1 prefix=$2 chain=$3 cpu=$4 scratch=$5 machine=mps2-an386
  [ "$cpu" = RV32 ] && machine=virt
  local dir="$scratch/stack-probe-$cpu"
  mkdir -p "$dir"
  cmake -S "$src/tests/firmware/stack" -B "$dir/build" -DCMAKE_TOOLCHAIN_FILE="$chain" \
    -DCMAKE_PREFIX_PATH="$prefix" -DHALOPLOT_SOURCE_DIR="$src" -DCMAKE_BUILD_TYPE=MinSizeRel \
    > "$dir/build.log" 2>&1 && cmake --build "$dir/build" >> "$dir/build.log" 2>&1 ||
    { cat "$dir/build.log"; echo "FAILED: the stack probe for $cpu does not build"; return 1; }
  local rc=0
  qemu_run "$machine" "$dir/build/stack_probe.elf" > "$dir/out" 2>&1 || rc=$?
  if [ "$rc" -ne 0 ]; then
    cat "$dir/out"; echo "FAILED: the stack probe for $cpu exited $rc"; return 1
  fi
  # The stated figures: docs/porting.md's table.
  sed -n '/<!-- stack-table/,/<!-- \/stack-table -->/p' "$src/docs/porting.md" | grep '^|' > "$dir/table"
  stack_compare "$dir/out" "$dir/table" "$cpu" || { echo "FAILED: the stack of $cpu"; return 1; }
  # The comparison's bad case: job_prepare's figure 8 bytes below what was measured.
  local measured
  measured=$(sed -n 's/^fw stack job_prepare=//p' "$dir/out")
  awk -F'|' -v cpu="$cpu" -v v="$((measured - 8))" '
    function trim(s) { gsub(/^[ \t`]+|[ \t`]+$/, "", s); return s }
    NR == 1 { for (i = 2; i < NF; ++i) if (trim($i) == cpu) col = i }
    NR > 1 && trim($2) == "job_prepare" { $col = " " v " " }
    { print }' OFS='|' "$dir/table" > "$dir/planted"
  if stack_compare "$dir/out" "$dir/planted" "$cpu" > "$dir/planted.out"; then
    cat "$dir/planted.out"; echo "FAILED: the stack check passed job_prepare over a planted figure"; return 1
  fi
  echo "stack $cpu: the check refuses job_prepare at a figure 8 bytes under its $measured"
}
