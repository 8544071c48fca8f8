#!/usr/bin/env bash
# Boots the Cortex-M4 CUT benchmark image under QEMU (-icount) and checks every row's crossing
# count against the host's CUT on the same scene (same generator, same seed), so the chip's
# instruction counts are counts of a correct run. Usage: FIRMWARE_DIR HALOPLOT_TOOL
set -u
fw="$1"
tool="$2"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
pass=0 fail=0
if [ ! -f "$fw/fw_cut_bench.elf" ]; then
  echo "FAILED: $fw/fw_cut_bench.elf is missing: build the firmware preset first"
  echo "firmware_cut_bench: 0 passed, 1 failed"
  exit 1
fi
timeout 600 qemu-system-arm -M netduinoplus2 -nographic -monitor none -serial none \
  -semihosting-config enable=on,target=native -icount shift=0,align=off,sleep=off \
  -kernel "$fw/fw_cut_bench.elf" > "$work/out.txt"
rc=$?
if [ "$rc" -eq 0 ]; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAILED: exit status $rc"; fi
while read -r _ _ n l seed crossings instructions pairs; do
  length=$(printf '0.%06d' "$l")
  "$tool" random-scene --edges "$n" --length "$length" --seed "$seed" -o "$work/s.edges"
  stats=$("$tool" cut "$work/s.edges" -o "$work/s.cut" --stats 2>&1)
  host=$(( $(sed -n 's/^crossings=//p' <<<"$stats") + $(sed -n 's/^equal_depth=//p' <<<"$stats") ))
  echo "N=$n L=$length seed=$seed: chip $crossings crossings in $instructions instructions, host $host"
  if [ "$crossings" = "$host" ]; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAILED: crossings differ"; fi
done < <(grep '^fw row ' "$work/out.txt")
[ "$pass" -ge 6 ] || { fail=$((fail + 1)); echo "FAILED: expected 5 rows"; }
echo "firmware_cut_bench: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
