# Shared by the QEMU tests (sourced, not run): arguments, a scratch folder, pass/fail counters,
# the one QEMU command line every image boots with, and the missing-image check.
# Usage in a test: source qemu_common.sh TEST_NAME FIRMWARE_DIR HALOPLOT_TOOL IMAGE...
set -u
test_name="$1"
fw="$2"
tool="$3"
shift 3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
pass=0 fail=0
ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAILED: $*" >&2; }
# netduinoplus2 is QEMU's STM32F405; -icount makes virtual time count instructions.
qemu() {
  timeout 600 qemu-system-arm -M netduinoplus2 -nographic -monitor none -serial none \
    -semihosting-config enable=on,target=native -icount shift=0,align=off,sleep=off -kernel "$1"
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
