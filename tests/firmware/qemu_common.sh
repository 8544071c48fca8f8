# Shared by the QEMU tests (sourced, not run): arguments, a scratch folder, pass/fail counters,
# the one QEMU command line every image boots with, and the missing-image check.
# Usage in a test: source qemu_common.sh TEST_NAME FIRMWARE_DIR HALOPLOT_TOOL IMAGE...
set -u
test_name="$1"
repo_root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)  # before any test changes folder
fw="$2"
tool="$3"
shift 3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
pass=0 fail=0
ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAILED: $*" >&2; }
# The board's QEMU machine: netduinoplus2 is QEMU's STM32F405 (the default); a test of another
# board sets HALOPLOT_QEMU_MACHINE (mps2-an385 for boards/mps2_an385). -icount makes virtual
# time count instructions.
machine=${HALOPLOT_QEMU_MACHINE:-netduinoplus2}
# The emulator and the command line: qemu_run.sh (qemu-system-arm for the Cortex-M machines,
# qemu-system-riscv32 for `virt`; semihosting and -icount on both).
source "$(dirname "${BASH_SOURCE[0]}")/qemu_run.sh"
read -r -a emulator <<< "$(qemu_emulator "$machine")"
# The wall-clock limits here (and the tests' CTest TIMEOUT) are backstops for a hung emulator
# only, ten times and more what a run takes on a quiet machine: the test command must pass with
# the machine loaded several times over. Liveness is checked by progress instead: a controller
# that stops answering fails `send` after 20 unanswered tries of a request (send_job).
qemu() { qemu_run "$machine" "$1"; }
# The controller image with USART1 on a Unix socket ($work/link.sock), in the background:
# its semihosting output in $work/fw.out, its pid in qemu_pid. Usage: qemu_linked SECONDS IMAGE
qemu_linked() {
  timeout "$1" "${emulator[@]}" -nographic -monitor none \
    -chardev socket,id=link,path="$work/link.sock",server=on,wait=off -serial chardev:link \
    -semihosting-config enable=on,target=native -icount shift=0,align=off,sleep=off \
    -kernel "$2" > "$work/fw.out" 2> "$work/qemu.err" &
  qemu_pid=$!
}
# `haloplot send JOB [options]` to the controller that qemu_linked started. Each reply may take
# up to 30 s, not the 3 s a serial link wants: on a loaded machine the emulated controller
# can answer late, and a request resent 20 times unanswered would fail the test. Damaged
# frames are still found at once (the controller NAKs them; the tests' damaged sessions see
# no timeouts), and a dead controller still fails it: its socket closes and `send` gives up
# at once, and qemu_linked's timeout ends a hung one.
send_job() { "$tool" send "$1" --port "$work/link.sock" --reply-timeout 30000 "${@:2}"; }
# A trace file's CRC-32 and length (gzip's trailer holds the CRC-32 of what it compressed),
# as a test image prints them for its own trace: "CRC BYTES".
trace_digest() {
  local crc _
  read -r crc _ < <(gzip -c "$1" | tail -c 8 | od -An -tu4)
  echo "$crc $(wc -c < "$1")"
}
# Is the image's trace (its "fw trace_crc32=" and "fw trace_bytes=" lines in FILE) the one
# of the host's trace? Usage: same_digest FW_OUT "CRC BYTES"
same_digest() {
  local crc bytes
  crc=$(sed -n 's/^fw trace_crc32=//p' "$1")
  bytes=$(sed -n 's/^fw trace_bytes=//p' "$1")
  [ -n "$crc" ] && [ "$crc $bytes" = "$2" ]
}
# The README's demo job (scenes/demo.job) on the demo scene with `arena ARENA` (and any
# further job LINE, which overrides the demo's), in $work, and `haloplot sim` of it: prints the
# digest of the host's trace; its --stats in $work/host.stats.
# Usage: demo_job_digest ARENA [LINE]
demo_job_digest() {
  "$tool" demo-scene -o "$work/demo.edges"
  sed -e 's|^scene .*|scene demo.edges|' "$repo_root/scenes/demo.job" > "$work/demo.job"
  echo "arena $1" >> "$work/demo.job"
  [ -z "${2:-}" ] || echo "$2" >> "$work/demo.job"
  "$tool" sim "$work/demo.job" -o "$work/host.trace" --stats 2> "$work/host.stats"
  trace_digest "$work/host.trace"
  rm -f "$work/host.trace"
}
# After the session's last `send` (its exit status rc, its output in send.out, in $work): the
# send and the controller image must both end well; prints the image's counters.
end_session() {
  cat "$work/send.out"
  if [ "$1" -eq 0 ]; then ok; else bad "send failed ($1)"; kill "$qemu_pid"; fi
  wait "$qemu_pid"
  local code=$?
  if [ "$code" -eq 0 ]; then ok; else bad "controller exit status $code: $(cat "$work/qemu.err")"; fi
  grep '^fw ' "$work/fw.out"
  echo "controller session: $((SECONDS - start)) s"
}
finish() {
  echo "$test_name: $pass passed, $fail failed"
  [ "$fail" -eq 0 ]
}
for image in "$@"; do
  if [ ! -f "$fw/$image" ]; then
    echo "FAILED: $fw/$image is missing: build the firmware preset first (cmake --build --preset firmware)"
    echo "$test_name: 0 passed, 1 failed"
    exit 1
  fi
done
