#!/usr/bin/env bash
# A scene the controller never holds, plotted by the controller image from `haloplot send` in
# bands into its band arena. JOB is
#   demo    the README's demo: Figure 4 (9408 edges, halo 50, the demo machine at a quarter of a
#           motor step per plot step), its edges
#           streamed band by band into 64 KB;
#   solid   a 10 x 10 solid cube array (800 vertices, 1200 edges, 1200 triangles) hidden-dashed
#           with outlines and hatching, each band's vertices, edges and triangles streamed into
#           64 KB, its hidden lines, outlines and hatch lines worked out on the controller band
#           by band;
#   dashed  the 6 x 6 solid cubes of band_dashes (tests/cli/band_dashes.sh), hidden-dashed with
#           outlines and hatching, streamed into 48 KB (8 bands), the controller's whole trace
#           read back (not its digest);
#   cubes28 the 28 x 28 solid cubes (6,272 vertices, 9,408 edges, 9,408 triangles), hidden-dashed
#           with outlines and hatching, streamed into 64 KB (54 bands across the page turned a
#           quarter), the banded plot checked against the whole-model one on the host.
# Checks that the controller's step trace equals `haloplot sim` of the same job (the same
# arena), byte for byte (for demo and solid the image sums its trace to a CRC-32 and a length, a
# test hook; gzip's trailer gives the host's), that it took more than one band (dashed: five or
# more), and that the image exits 0. The plot may wait for a band (an underrun): the trace must
# not show it. For dashed also that the controller draws the whole-model plot (`sim` of the job
# without its arena), stroke for stroke with every dash end within a step, by band_dashes_check
# (tests/tools/band_dashes_check.cpp, which reads the traces alone), and that the check fails
# against the whole-model plot with other gaps between the dashes. Slow under QEMU (millions of
# step interrupts: minutes), so the sanitizer build skips it.
# Usage: qemu_stream_test.sh FIRMWARE_DIR HALOPLOT_TOOL [demo|solid|dashed|cubes28]
#          [BAND_DASHES_CHECK]
kind=${3:-demo}
check=${4:-}
source "$(dirname "$0")/qemu_common.sh" "firmware_stream ($kind)" "$1" "$2" fw_plotter_qemu.elf
if { [ "$kind" = dashed ] || [ "$kind" = cubes28 ]; } && [ ! -x "$check" ]; then
  echo "FAILED: no band_dashes_check at '$check' (the fourth argument)"
  echo "$test_name: 0 passed, 1 failed"
  exit 1
fi

cd "$work"
# check_picture BANDED WHAT: BANDED draws whole.trace's picture, stroke for stroke within a
# step (band_dashes_check), and the check tells it from other_gaps.trace (1.05 mm gaps, not 1):
# exit status 1 is "the drawings differ"; 2 would be a trace the check could not read.
check_picture() {
  local out rc
  out=$("$check" whole.trace "$1")
  rc=$?
  echo "$2 against the whole-model plot: $out"
  if [ "$rc" -eq 0 ]; then ok; else bad "$2 draws another picture than the whole-model plot"; fi
  out=$("$check" other_gaps.trace "$1")
  rc=$?
  echo "against the whole-model plot with 1.05 mm gaps (must differ): $out"
  if [ "$rc" -eq 1 ]; then ok; else bad "the check did not tell 1.05 mm gaps from 1 mm ones (exit status $rc)"; fi
}
min_bands=2
send_opts=(--trace-digest)
if [ "$kind" = solid ]; then
  "$tool" demo-scene --cubes 10 -o cubes10.obj
  # A sixteenth of a motor step per plot step: the same 10 bands, hidden lines and hatching
  # worked out on the chip and the same link traffic, a sixteenth of the step interrupts, where
  # QEMU's time goes (161,000 steps a motor; at a quarter, 200 s of the test command's time).
  # The step interrupt at finer steps is firmware_link's and firmware_stream_dashed's.
  # With --simplify: the controller leaves out the same points as the host (motion/stroke_simplify.h).
  printf 'scene cubes10.obj\ndrawing hidden-dashed\nview 30,25\ndash 2 1\noutline on\nhatch 3 30 90\nkinematics corexy\nsteps 1/16\narena 65536\nsimplify 0.1\n' \
    > demo.job
  "$tool" sim demo.job -o host.trace --stats 2> host.stats
  host=$(trace_digest host.trace)
  rm -f host.trace
elif [ "$kind" = cubes28 ]; then
  "$tool" demo-scene --cubes 28 -o cubes28.obj
  # The 28 x 28 cubes (6,272 vertices, 9,408 edges, 9,408 triangles) hidden-dashed with outlines
  # and hatching in 64 KB, each band's part streamed: the controller works out the hidden lines
  # of every band itself. A sixteenth of a motor step per plot step, as for solid.
  # (Clean-up off: a band has one pen and merges overlaps across kinds of line, the whole-model
  # plot only within a layer, as in band_dashes.)
  printf 'scene cubes28.obj\ndrawing hidden-dashed\nview 30,25\ndash 2 1\noutline on\nhatch 3 30 90\neffects acceleration pen-servo\nkinematics corexy\nsteps 1/16\ncleanup off\n' \
    > whole.job
  { cat whole.job; echo "arena 65536"; } > demo.job
  "$tool" sim demo.job -o host.trace --stats 2> host.stats
  host=$(trace_digest host.trace)
  min_bands=10
  # The controller's trace is checked by its digest against this banded plot's; that the
  # banded plot draws the whole-model one is checked here, on the host, and that the check
  # tells other gaps apart (as for dashed). At a quarter of a motor step: the same bands and
  # strokes, rounded to a finer grid. At an eighth or a sixteenth the check fails on a stroke
  # of one motor step that a border splits at a rounded point within half a step of it (its
  # pieces pair with nothing; the ink agrees), so it is not the check's grid here.
  sed 's|^steps 1/16$|steps 1/4|' whole.job > whole4.job
  { cat whole4.job; echo "arena 65536"; } > banded4.job
  sed 's/^dash 2 1$/dash 2 1.05/' whole4.job > other_gaps.job
  "$tool" sim whole4.job -o whole.trace
  "$tool" sim banded4.job -o banded4.trace
  "$tool" sim other_gaps.job -o other_gaps.trace
  check_picture banded4.trace "sim in bands"
  rm -f whole.trace banded4.trace other_gaps.trace
elif [ "$kind" = dashed ]; then
  "$tool" demo-scene --cubes 6 -o cubes6.obj
  # band_dashes' hatched cubes (its keys; `dash 2 1` is the default, written out for the other
  # gaps below) at an eighth of a motor step per plot step: the same strokes, an eighth of the
  # step interrupts (64 s at a quarter, 36 to 41 s at an eighth, on a 2-core machine with other
  # builds running). The check's step is then a motor step, 8 plot steps (0.1 mm). 48 KB: 8
  # bands (10 in the page's rows).
  # (Clean-up off, as for cubes28.)
  printf 'scene cubes6.obj\ndrawing hidden-dashed\nview 30,25\ndash 2 1\noutline on\nhatch 3 30 90\neffects acceleration pen-servo\nkinematics corexy\nsteps 1/8\ncleanup off\n' \
    > whole.job
  { cat whole.job; echo "arena 49152"; } > demo.job
  "$tool" sim whole.job -o whole.trace
  "$tool" sim demo.job -o host.trace --stats 2> host.stats
  # The same job's whole-model plot with gaps of 1.05 mm, not 1 (4 plot steps longer, half a
  # motor step): the check must tell it apart.
  sed 's/^dash 2 1$/dash 2 1.05/' whole.job > other_gaps.job
  "$tool" sim other_gaps.job -o other_gaps.trace
  # Borders for the dashes to run across.
  min_bands=5
  # The whole trace: the strokes are read from it, not only its digest.
  send_opts=()
else
  # A sixteenth of a motor step per plot step: the same bands, edges and link traffic, a
  # sixteenth of the step interrupts, where QEMU's time goes (128 s at a quarter, 52 s at a
  # sixteenth, alone on a 2-core machine: the step events of an 83-minute plot). Figure 4's
  # whole steps on the chip in 64 KB are firmware_bands' (the band self-test, no link).
  host=$(demo_job_digest 65536 "steps 1/16")
fi

qemu_linked 3000 "$fw/fw_plotter_qemu.elf"
start=$SECONDS
send_job demo.job "${send_opts[@]}" --test-exit > send.out 2>&1
end_session $?
if [ "$kind" = dashed ]; then
  awk '/^haloplot-trace 2$/ { on = 1 } on { print > "fw.trace" } /^end / { on = 0 }' fw.out
  if [ -s fw.trace ] && cmp -s fw.trace host.trace; then
    ok
    echo "trace identical to haloplot sim of the banded job: $(wc -c < host.trace) bytes"
  else
    bad "controller trace ($(wc -c < fw.trace 2>/dev/null) bytes) differs from haloplot sim of the banded job ($(wc -c < host.trace) bytes)"
  fi
  check_picture fw.trace "the controller's banded plot"
elif same_digest fw.out "$host"; then
  ok
  echo "traces identical (CRC-32 and bytes): $host"
else
  bad "controller trace ($(grep '^fw trace_' fw.out | tr '\n' ' ')) differs from haloplot sim ($host)"
fi
bands=$(sed -n 's/^bands=//p' host.stats)
arena=$(sed -n 's/^arena //p' demo.job)
if [ "${bands:-0}" -ge "$min_bands" ] && grep -q "^streamed $bands bands" send.out; then
  ok
  echo "$bands bands, peak $(sed -n 's/^band_peak_bytes=//p' host.stats) bytes of the $arena-byte arena"
else
  bad "bands (at least $min_bands): sim $bands, send: $(grep '^streamed' send.out)"
fi
finish
