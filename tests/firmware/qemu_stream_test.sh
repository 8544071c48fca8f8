#!/usr/bin/env bash
# The README's demo plotted by the controller image from `haloplot send`: Figure 4 (9408 edges,
# halo 50, the demo machine) streamed in bands into a 64 KB band arena, the controller never
# holding the scene. Checks that the controller's step trace equals `haloplot sim` of the same
# job with `arena 65536`, byte for byte (the image sums its 45 MB trace to a CRC-32 and a
# length, a test hook; gzip's trailer gives the host's), that it took more than one band, and
# that the image exits 0. The plot may wait for a band (an underrun): the trace must not show it.
# Slow under QEMU (4 million step interrupts: several minutes), so the sanitizer build skips it.
# Usage: qemu_stream_test.sh FIRMWARE_DIR HALOPLOT_TOOL
source "$(dirname "$0")/qemu_common.sh" firmware_stream "$1" "$2" fw_plotter_qemu.elf
src=$(cd "$(dirname "$0")/../.." && pwd)

cd "$work"
"$tool" demo-scene -o demo.edges
sed -e 's|^scene .*|scene demo.edges|' "$src/scenes/demo.job" > demo.job
echo "arena 65536" >> demo.job
"$tool" sim demo.job -o host.trace --stats 2> host.stats
read -r host_crc host_len < <(gzip -c host.trace | tail -c 8 | od -An -tu4)
host_bytes=$(wc -c < host.trace)
rm -f host.trace

timeout 1500 qemu-system-arm -M netduinoplus2 -nographic -monitor none \
  -chardev socket,id=link,path="$work/link.sock",server=on,wait=off -serial chardev:link \
  -semihosting-config enable=on,target=native -icount shift=0,align=off,sleep=off \
  -kernel "$fw/fw_plotter_qemu.elf" > fw.out 2> qemu.err &
qemu_pid=$!
start=$SECONDS
"$tool" send demo.job --port "$work/link.sock" --trace-digest --test-exit > send.out 2>&1
rc=$?
cat send.out
if [ "$rc" -eq 0 ]; then ok; else bad "send failed ($rc)"; kill "$qemu_pid"; fi
wait "$qemu_pid"
rc=$?
if [ "$rc" -eq 0 ]; then ok; else bad "controller exit status $rc: $(cat qemu.err)"; fi
grep '^fw ' fw.out
echo "controller session: $((SECONDS - start)) s"
fw() { sed -n "s/^fw $1=//p" fw.out; }
if [ -n "$(fw trace_crc32)" ] && [ "$(fw trace_crc32)" = "$host_crc" ] &&
   [ "$(fw trace_bytes)" = "$host_bytes" ]; then
  ok
  echo "traces identical: $host_bytes bytes, CRC-32 $host_crc"
else
  bad "controller trace (CRC $(fw trace_crc32), $(fw trace_bytes) bytes) differs from haloplot sim (CRC $host_crc, $host_bytes bytes)"
fi
bands=$(sed -n 's/^bands=//p' host.stats)
if [ "${bands:-0}" -gt 1 ] && grep -q "^streamed $bands bands" send.out; then
  ok
else
  bad "bands: sim $bands, send: $(grep '^streamed' send.out)"
fi
finish
