#!/usr/bin/env bash
# Boots the memory-contract image (firmware/selftest/misaligned_selftest.cpp) under QEMU: every
# public entry that takes a caller buffer, at offsets 0 to 8 from an 8-byte boundary, must
# answer kMisalignedBuffer (1-7) or its aligned result (8), never fault. A fault hangs the image
# in its fault handler: the run's time limit, far above the second it takes, turns that into a
# failure. The board's machine comes from HALOPLOT_QEMU_MACHINE (qemu_common.sh).
# Usage: qemu_misaligned_test.sh FIRMWARE_DIR
source "$(dirname "$0")/qemu_common.sh" firmware_misaligned "$1" none fw_misaligned_selftest.elf

timeout 300 qemu-system-arm -M "$machine" -nographic -monitor none -serial none \
  -semihosting-config enable=on,target=native -icount shift=0,align=off,sleep=off \
  -kernel "$fw/fw_misaligned_selftest.elf" > "$work/out.txt"
rc=$?
cat "$work/out.txt"
if [ "$rc" -eq 124 ]; then
  bad "the image did not finish (a fault hangs it in the fault handler)"
elif [ "$rc" -ne 0 ]; then
  bad "exit status $rc"
else
  ok
fi
checks=$(sed -n 's/^fw misaligned checks=\([0-9]*\) failed=0$/\1/p' "$work/out.txt")
# 14 entries (and buffers) at 9 offsets each.
if [ "${checks:-0}" -ge 126 ]; then ok; else bad "expected at least 126 checks, all passed"; fi
finish
