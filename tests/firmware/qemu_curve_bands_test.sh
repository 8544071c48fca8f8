#!/usr/bin/env bash
# A curve job in bands on the controller: the demo trefoil (24 cubic Bézier edges) as a job with
# `arena 24576`, less than the whole drawing takes in one band, uploaded by `haloplot send` as
# curves with that band arena (kUploadBegin's 21-byte form); the controller image draws it band
# by band in that many bytes of its arena (band/curve_bands.h) while the pen moves. Checks that:
#   - the controller's step trace equals `haloplot sim` of the same job, byte for byte (summed
#     to a CRC-32 and a length by a test hook; gzip's trailer gives the host's);
#   - the banded trace is not the unbanded job's (sim of the job without its arena must differ:
#     a controller that drew the job whole would fail the comparison), nor the banded job's at
#     a halo one step wider;
#   - sim took more than one band; the image exits 0 with no step underrun.
# (That the banded plot's pen-down segments are the unbanded plot's within a step is
# curve_bands_cli's check, on the same job.)
# Usage: qemu_curve_bands_test.sh FIRMWARE_DIR HALOPLOT_TOOL
source "$(dirname "$0")/qemu_common.sh" "firmware_curve_bands" "$1" "$2" fw_plotter_qemu.elf

cd "$work"
"$tool" demo-scene --curve trefoil -o trefoil.edges
job() {  # job NAME HALO [ARENA]
  printf 'scene trefoil.edges\ndrawing haloed\nhalo %s\nhalo-mode paper\nkinematics corexy\nsteps 1/4\n' \
    "$2" > "$1"
  if [ -n "${3:-}" ]; then echo "arena $3" >> "$1"; fi
}
job band.job 80 24576
job whole.job 80
job wider.job 81 24576
"$tool" sim band.job -o host.trace --stats 2> host.stats
host=$(trace_digest host.trace)
"$tool" sim whole.job -o whole.trace
whole=$(trace_digest whole.trace)
"$tool" sim wider.job -o wider.trace
wider=$(trace_digest wider.trace)
rm -f host.trace whole.trace wider.trace
bands=$(sed -n 's/^bands=//p' host.stats)
if [ "${bands:-0}" -ge 2 ]; then
  ok
  echo "sim: $bands bands in 24576 bytes, peak $(sed -n 's/^band_peak_bytes=//p' host.stats)"
else
  bad "sim of the banded job took ${bands:-no} bands"
fi
if [ "$host" != "$whole" ] && [ "$host" != "$wider" ]; then
  ok
else
  bad "the banded trace equals the unbanded job's or the halo-81 one's: the comparison could not tell"
fi

qemu_linked 600 "$fw/fw_plotter_qemu.elf"
start=$SECONDS
send_job band.job --trace-digest --test-exit > send.out 2>&1
end_session $?
if same_digest fw.out "$host"; then
  ok
  echo "traces identical (CRC-32 and bytes): $host"
else
  bad "controller trace ($(sed -n 's/^fw trace_crc32=//p' fw.out) $(sed -n 's/^fw trace_bytes=//p' fw.out)) differs from haloplot sim ($host)"
fi
if grep -q "^plot: .* edges=24 " send.out; then
  ok
else
  bad "the controller should report the trefoil's 24 edges: $(grep '^plot:' send.out)"
fi
if grep -q '^fw underruns=0$' fw.out; then ok; else bad "step underruns: $(grep underruns fw.out)"; fi
finish
