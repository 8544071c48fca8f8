#!/usr/bin/env bash
# Boots the STM32F405 self-test image under QEMU (netduinoplus2, -icount for determinism),
# and checks that:
#   - the image exits 0 through semihosting (and the hello image's exit 3 comes through as 3);
#   - its step trace equals `haloplot sim` for the same job, byte for byte (the chip's 32-bit
#     arithmetic against the host's 64-bit build of the same core);
#   - its crossing count equals the host's.
# Usage: qemu_plot_test.sh FIRMWARE_DIR HALOPLOT_TOOL
set -u
fw="$1"
tool="$2"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
pass=0 fail=0
ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAILED: $*" >&2; }
qemu() {
  timeout 600 qemu-system-arm -M netduinoplus2 -nographic -monitor none -serial none \
    -semihosting-config enable=on,target=native -icount shift=0,align=off,sleep=off -kernel "$1"
}
for image in fw_hello.elf fw_plot_selftest.elf; do
  if [ ! -f "$fw/$image" ]; then
    echo "FAILED: $fw/$image is missing: build the firmware preset first (cmake --build --preset firmware)"
    echo "firmware_plot: 0 passed, 1 failed"
    exit 1
  fi
done

qemu "$fw/fw_hello.elf" > "$work/hello.out"
rc=$?
if [ "$rc" -eq 3 ]; then ok; else bad "hello image exit status $rc, expected 3"; fi

qemu "$fw/fw_plot_selftest.elf" > "$work/fw.out"
rc=$?
if [ "$rc" -eq 0 ]; then ok; else bad "self-test exit status $rc: $(grep FAILED "$work/fw.out")"; fi
grep '^fw ' "$work/fw.out"
sed -n '/^haloplot-trace 1$/,/^end /p' "$work/fw.out" > "$work/fw.trace"

cd "$work"
"$tool" demo-scene --cubes 6 -o scene.edges
printf 'scene scene.edges\ndrawing haloed\nhalo 50\nhalo-mode paper\nkinematics corexy\n' > job.job
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
echo "firmware_plot: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
