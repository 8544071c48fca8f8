#!/usr/bin/env bash
# Boots the band self-test image under QEMU: the README's demo (Figure 4, 9408 edges, halo 50)
# plotted on the chip in a 64 KB job arena, band by band. Checks that:
#   - the image exits 0 and used at most its arena;
#   - its step trace equals `haloplot sim` of the demo job with `arena 65536`, byte for byte
#     (the chip sends the trace's CRC-32 and length; gzip's trailer gives the host's);
#   - it drew in more than one band (the scene does not fit the arena whole).
# Usage: qemu_band_test.sh FIRMWARE_DIR HALOPLOT_TOOL
source "$(dirname "$0")/qemu_common.sh" firmware_bands "$1" "$2" fw_band_selftest.elf
src=$(cd "$(dirname "$0")/../.." && pwd)

qemu "$fw/fw_band_selftest.elf" > "$work/fw.out"
rc=$?
if [ "$rc" -eq 0 ]; then ok; else bad "band self-test exit status $rc: $(grep FAILED "$work/fw.out")"; fi
grep '^fw ' "$work/fw.out"
stat() { sed -n "s/^fw $1=//p" "$work/fw.out"; }

cd "$work"
"$tool" demo-scene -o demo.edges
sed -e 's|^scene .*|scene demo.edges|' "$src/scenes/demo.job" > demo.job
echo "arena 65536" >> demo.job
"$tool" sim demo.job -o host.trace --stats 2> host.stats
read -r host_crc host_len < <(gzip -c host.trace | tail -c 8 | od -An -tu4)
host_bytes=$(wc -c < host.trace)
if [ -n "$(stat trace_crc32)" ] && [ "$(stat trace_crc32)" = "$host_crc" ] &&
   [ "$(stat trace_bytes)" = "$host_bytes" ]; then
  ok
  echo "traces identical: $host_bytes bytes, CRC-32 $host_crc"
else
  bad "firmware trace (CRC $(stat trace_crc32), $(stat trace_bytes) bytes) differs from haloplot sim (CRC $host_crc, $host_bytes bytes)"
fi
host_bands=$(sed -n 's/^bands=//p' host.stats)
if [ "$(stat bands)" = "$host_bands" ] && [ "${host_bands:-0}" -gt 1 ]; then ok; else bad "bands: firmware $(stat bands), host $host_bands"; fi
if [ -n "$(stat peak_bytes)" ] && [ "$(stat peak_bytes)" -le 65536 ]; then ok; else bad "peak $(stat peak_bytes) bytes beyond the 64 KB arena"; fi
finish
