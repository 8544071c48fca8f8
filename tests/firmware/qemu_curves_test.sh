#!/usr/bin/env bash
# A scene with curved edges drawn by the controller itself: the demo trefoil (24 cubic Bézier
# edges) uploaded by `haloplot send` as curves (kUploadCurves) into the controller image, which
# finds the crossings, cuts the halo gaps and flattens the curves into chords in its arena
# (core/job job_prepare_curves), then plans and plots them. Checks that:
#   - the controller's step trace equals `haloplot sim` of the same job, byte for byte (summed
#     to a CRC-32 and a length by a test hook; gzip's trailer gives the host's);
#   - it is not the trace of the same job with a halo one step wider (sim of that job must
#     differ: the comparison can fail);
#   - a re-plot with that wider halo (`send --replot 81`: DRAW and the path again on the
#     crossings the plot kept, job_redraw_curves) plots sim's trace of the halo-81 job;
#   - the controller reports the knot's 3 crossings and its 24 edges;
#   - the image exits 0 with no step underrun.
# A quarter of a motor step per plot step, as the other QEMU tests run: the same curves and
# chords, a quarter of the step interrupts, where QEMU's time goes.
# Usage: qemu_curves_test.sh FIRMWARE_DIR HALOPLOT_TOOL
source "$(dirname "$0")/qemu_common.sh" "firmware_curves" "$1" "$2" fw_plotter_qemu.elf

cd "$work"
"$tool" demo-scene --curve trefoil -o trefoil.edges
job() {  # job NAME HALO
  printf 'scene trefoil.edges\ndrawing haloed\nhalo %s\nhalo-mode paper\nkinematics corexy\nsteps 1/4\n' \
    "$2" > "$1"
}
job curves.job 80
job wider.job 81
"$tool" sim curves.job -o host.trace --stats 2> host.stats
host=$(trace_digest host.trace)
"$tool" sim wider.job -o wider.trace
wider=$(trace_digest wider.trace)
rm -f host.trace wider.trace
if [ "$host" != "$wider" ]; then
  ok
else
  bad "sim of halo 80 and halo 81 give the same trace: the comparison could not tell them apart"
fi

qemu_linked 600 "$fw/fw_plotter_qemu.elf"
start=$SECONDS
send_job curves.job --replot 81 --trace-digest --test-exit > send.out 2>&1
end_session $?
# The plot's digest, then the re-plot's.
mapfile -t crcs < <(sed -n 's/^fw trace_crc32=//p' fw.out)
mapfile -t sizes < <(sed -n 's/^fw trace_bytes=//p' fw.out)
if [ "${crcs[0]:-} ${sizes[0]:-}" = "$host" ]; then
  ok
  echo "traces identical (CRC-32 and bytes): $host"
else
  bad "controller trace (${crcs[0]:-} ${sizes[0]:-}) differs from haloplot sim ($host)"
fi
if [ "${crcs[0]:-} ${sizes[0]:-}" = "$wider" ]; then
  bad "the controller's trace is also the halo-81 job's"
else
  ok
  echo "and differs from sim of the job with halo 81 ($wider)"
fi
if [ "${crcs[1]:-} ${sizes[1]:-}" = "$wider" ]; then
  ok
  echo "the re-plot at halo 81 is sim's trace of the halo-81 job: $wider" \
    "($(sed -n 's/^fw replot_instructions=//p' fw.out) instructions to re-plan)"
else
  bad "the re-plot's trace (${crcs[1]:-} ${sizes[1]:-}) is not sim's of the halo-81 job ($wider)"
fi
if grep -q "^plot: .* edges=24 crossings=3 " send.out; then
  ok
else
  bad "the controller should report 24 edges and the trefoil's 3 crossings: $(grep '^plot:' send.out)"
fi
if grep -q '^fw underruns=0$' fw.out; then ok; else bad "step underruns: $(grep underruns fw.out)"; fi
finish
