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

cd "$work"
host=$(demo_job_digest 65536)

qemu_linked 1500 "$fw/fw_plotter_qemu.elf"
start=$SECONDS
"$tool" send demo.job --port "$work/link.sock" --trace-digest --test-exit > send.out 2>&1
end_session $?
if same_digest fw.out "$host"; then
  ok
  echo "traces identical (CRC-32 and bytes): $host"
else
  bad "controller trace ($(grep '^fw trace_' fw.out | tr '\n' ' ')) differs from haloplot sim ($host)"
fi
bands=$(sed -n 's/^bands=//p' host.stats)
if [ "${bands:-0}" -gt 1 ] && grep -q "^streamed $bands bands" send.out; then
  ok
else
  bad "bands: sim $bands, send: $(grep '^streamed' send.out)"
fi
finish
