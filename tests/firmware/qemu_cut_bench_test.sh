#!/usr/bin/env bash
# Boots the Cortex-M4 CUT benchmark image under QEMU (-icount) and checks every row's crossing
# count against the host's CUT on the same scene (same generator, same seed), so the chip's
# instruction counts are counts of a correct run. Usage: FIRMWARE_DIR HALOPLOT_TOOL
source "$(dirname "$0")/qemu_common.sh" firmware_cut_bench "$1" "$2" fw_cut_bench.elf

qemu "$fw/fw_cut_bench.elf" > "$work/out.txt"
rc=$?
if [ "$rc" -eq 0 ]; then ok; else bad "exit status $rc"; fi
while read -r _ _ n l seed crossings instructions pairs; do
  length=$(printf '0.%06d' "$l")
  "$tool" random-scene --edges "$n" --length "$length" --seed "$seed" -o "$work/s.edges"
  stats=$("$tool" cut "$work/s.edges" -o "$work/s.cut" --stats 2>&1)
  host=$(( $(sed -n 's/^crossings=//p' <<<"$stats") + $(sed -n 's/^equal_depth=//p' <<<"$stats") ))
  echo "N=$n L=$length seed=$seed: chip $crossings crossings in $instructions instructions, host $host"
  if [ "$crossings" = "$host" ]; then ok; else bad "crossings differ"; fi
done < <(grep '^fw row ' "$work/out.txt")
[ "$pass" -ge 6 ] || bad "expected 5 rows"
finish
