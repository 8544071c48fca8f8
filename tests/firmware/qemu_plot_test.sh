#!/usr/bin/env bash
# Boots the STM32F405 self-test image under QEMU (netduinoplus2, -icount for determinism),
# and checks that:
#   - the image exits 0 through semihosting (and the hello image's exit 3 comes through as 3);
#   - its step trace equals `haloplot sim` for the same job, byte for byte (the chip's 32-bit
#     arithmetic against the host's 64-bit build of the same core);
#   - its crossing count equals the host's.
# Usage: qemu_plot_test.sh FIRMWARE_DIR HALOPLOT_TOOL
source "$(dirname "$0")/qemu_common.sh" firmware_plot "$1" "$2" fw_hello.elf fw_plot_selftest.elf

qemu "$fw/fw_hello.elf" > "$work/hello.out"
rc=$?
if [ "$rc" -eq 3 ]; then ok; else bad "hello image exit status $rc, expected 3"; fi

qemu "$fw/fw_plot_selftest.elf" > "$work/fw.out"
rc=$?
if [ "$rc" -eq 0 ]; then ok; else bad "self-test exit status $rc: $(grep FAILED "$work/fw.out")"; fi
grep '^fw ' "$work/fw.out"
sed -n '/^haloplot-trace 2$/,/^end /p' "$work/fw.out" > "$work/fw.trace"

cd "$work"
"$tool" demo-scene --cubes 6 -o scene.edges
# (min-stroke 0: the self-test image plans with the core's clean-up default, no minimum stroke.)
printf 'scene scene.edges\ndrawing haloed\nhalo 50\nhalo-mode paper\nkinematics corexy\nmin-stroke 0\n' > job.job
"$tool" sim job.job -o host.trace
if [ -s fw.trace ] && cmp -s fw.trace host.trace; then
  ok
  echo "traces identical: $(wc -c < host.trace) bytes"
else
  bad "firmware trace ($(wc -c < fw.trace) bytes) differs from haloplot sim ($(wc -c < host.trace) bytes)"
fi
host_crossings=$("$tool" plot scene.edges --halo 50 -o x.svg --stats 2>&1 | sed -n 's/^crossings=//p')
fw_crossings=$(sed -n 's/^fw crossings=//p' fw.out)
if [ -n "$fw_crossings" ] && [ "$fw_crossings" = "$host_crossings" ]; then ok; else bad "crossings: firmware $fw_crossings, host $host_crossings"; fi
# Hidden lines on the chip: 3 x 3 solid cubes at view 30,40, as `haloplot plot` draws them.
"$tool" demo-scene --cubes 3 -o cubes3.obj
"$tool" plot cubes3.obj --view 30,40 --mode hidden-removed -o cubes3.svg --spans cubes3.spans
host_visible=$(grep -c '^s .* 0$' cubes3.spans)
fw_visible=$(sed -n 's/^fw solid_visible_pieces=//p' fw.out)
if [ -n "$fw_visible" ] && [ "$fw_visible" = "$host_visible" ] && grep -q '^fw solid_used_qi=1$' fw.out; then
  ok
else
  bad "visible pieces of 3 x 3 solid cubes: firmware $fw_visible, host $host_visible"
fi
# Hatching on the chip (the hidden-line run's hatch lines) against `haloplot plot --hatch`. Not
# equal here: the host projects the .obj (Y-up, read back) and rounds 44 of the 72 depths a
# unit apart from the chip's own cubes, which turns a few polygons' hatch by a millidegree and
# moves their lattice; within a tenth. (Byte-equal hatching of one projection on both sides:
# firmware_stream_solid's trace, and the job_server test's strokes.)
# Franklin's regions, hatched on the chip too, fill the same faces (their strokes cross a
# polygon's diagonal whole, so there are fewer of them, but as many as half the lines').
"$tool" plot cubes3.obj --view 30,40 --mode hidden-removed --hatch 3,45,90 -o cubes3h.svg \
  --spans cubes3h.spans
host_hatch=$(grep -c '^h ' cubes3h.spans)
fw_hatch=$(sed -n 's/^fw solid_hatch_strokes=//p' fw.out)
if [ -n "$fw_hatch" ] && [ "$host_hatch" -gt 20 ] && [ $((10 * (fw_hatch - host_hatch))) -le "$host_hatch" ] &&
  [ $((10 * (host_hatch - fw_hatch))) -le "$host_hatch" ]; then
  ok
else
  bad "hatch strokes of 3 x 3 solid cubes: firmware $fw_hatch, host $host_hatch"
fi
fw_regions=$(sed -n 's/^fw solid_region_hatch_strokes=//p' fw.out)
if [ -n "$fw_regions" ] && [ "$fw_regions" -le "$fw_hatch" ] && [ $((2 * fw_regions)) -ge "$fw_hatch" ]; then
  ok
else
  bad "Franklin's region hatching on the chip: $fw_regions strokes against the lines' $fw_hatch"
fi
finish
