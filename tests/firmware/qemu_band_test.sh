#!/usr/bin/env bash
# Boots the band self-test image under QEMU: the README's demo (Figure 4, 9408 edges, halo 50)
# plotted on the chip in a 64 KB job arena, band by band. Checks that:
#   - the image exits 0 and used at most its arena;
#   - its step trace equals `haloplot sim` of the demo job with `arena 65536`, byte for byte
#     (the chip sends the trace's CRC-32 and length; gzip's trailer gives the host's);
#   - it drew in more than one band (the scene does not fit the arena whole).
# Usage: qemu_band_test.sh FIRMWARE_DIR HALOPLOT_TOOL
source "$(dirname "$0")/qemu_common.sh" firmware_bands "$1" "$2" fw_band_selftest.elf

qemu "$fw/fw_band_selftest.elf" > "$work/fw.out"
rc=$?
if [ "$rc" -eq 0 ]; then ok; else bad "band self-test exit status $rc: $(grep FAILED "$work/fw.out")"; fi
grep '^fw ' "$work/fw.out"
fwstat() { sed -n "s/^fw $1=//p" "$work/fw.out"; }

cd "$work"
host=$(demo_job_digest 65536)
if same_digest "$work/fw.out" "$host"; then
  ok
  echo "traces identical (CRC-32 and bytes): $host"
else
  bad "firmware trace ($(grep '^fw trace_' "$work/fw.out" | tr '\n' ' ')) differs from haloplot sim ($host)"
fi
host_bands=$(sed -n 's/^bands=//p' host.stats)
if [ "$(fwstat bands)" = "$host_bands" ] && [ "${host_bands:-0}" -gt 1 ]; then ok; else bad "bands: firmware $(fwstat bands), host $host_bands"; fi
if [ -n "$(fwstat peak_bytes)" ] && [ "$(fwstat peak_bytes)" -le 65536 ]; then ok; else bad "peak $(fwstat peak_bytes) bytes beyond the 64 KB arena"; fi
finish
