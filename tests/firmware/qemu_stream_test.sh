#!/usr/bin/env bash
# A scene the controller never holds, plotted by the controller image from `haloplot send` in
# bands into a 64 KB band arena. JOB is
#   demo   the README's demo: Figure 4 (9408 edges, halo 50, the demo machine at a quarter of a
#          motor step per plot step), its edges
#          streamed band by band;
#   solid  a 10 x 10 solid cube array (800 vertices, 1200 edges, 1200 triangles) hidden-dashed
#          with outlines and hatching, each band's vertices, edges and triangles streamed, its
#          hidden lines, outlines and hatch lines worked out on the controller band by band.
# Checks that the controller's step trace equals `haloplot sim` of the same job with
# `arena 65536`, byte for byte (the image sums its trace to a CRC-32 and a length, a test hook;
# gzip's trailer gives the host's), that it took more than one band, and that the image exits 0.
# The plot may wait for a band (an underrun): the trace must not show it. Slow under QEMU
# (millions of step interrupts: minutes), so the sanitizer build skips it.
# Usage: qemu_stream_test.sh FIRMWARE_DIR HALOPLOT_TOOL [demo|solid]
kind=${3:-demo}
source "$(dirname "$0")/qemu_common.sh" "firmware_stream ($kind)" "$1" "$2" fw_plotter_qemu.elf

cd "$work"
if [ "$kind" = solid ]; then
  "$tool" demo-scene --cubes 10 -o cubes10.obj
  # A quarter of a motor step per plot step: the same bands and hidden lines, a quarter of the
  # step interrupts (QEMU's time goes to them).
  printf 'scene cubes10.obj\ndrawing hidden-dashed\nview 30,25\ndash 2 1\noutline on\nhatch 3 30 90\nkinematics corexy\nsteps 1/4\narena 65536\n' \
    > demo.job
  "$tool" sim demo.job -o host.trace --stats 2> host.stats
  host=$(trace_digest host.trace)
  rm -f host.trace
else
  # A sixteenth of a motor step per plot step: the same bands, edges and link traffic, a
  # sixteenth of the step interrupts, where QEMU's time goes (128 s at a quarter, 52 s at a
  # sixteenth, alone on a 2-core machine: the step events of an 83-minute plot). Figure 4's
  # whole steps on the chip in 64 KB are firmware_bands' (the band self-test, no link).
  host=$(demo_job_digest 65536 "steps 1/16")
fi

qemu_linked 3000 "$fw/fw_plotter_qemu.elf"
start=$SECONDS
send_job demo.job --trace-digest --test-exit > send.out 2>&1
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
  echo "$bands bands, peak $(sed -n 's/^band_peak_bytes=//p' host.stats) bytes of the 64 KB arena"
else
  bad "bands: sim $bands, send: $(grep '^streamed' send.out)"
fi
finish
