# The one QEMU command line every test image boots with (sourced): the machine's emulator
# (qemu-system-arm for the Cortex-M machines; for `virt`, QEMU's RISC-V machine,
# qemu-system-riscv32 -bios none: the image starts at the first word of RAM, in machine mode),
# semihosting for its output and exit status, -icount so virtual time counts instructions. The
# wall-clock limit is a backstop for a hung emulator only (qemu_common.sh says why).
# Usage: qemu_run MACHINE IMAGE [MORE QEMU OPTIONS...]
qemu_emulator() {
  case "$1" in
    virt) echo "qemu-system-riscv32 -M virt -bios none" ;;
    *) echo "qemu-system-arm -M $1" ;;
  esac
}
qemu_run() {
  local machine=$1 image=$2
  shift 2
  # shellcheck disable=SC2046
  timeout 1800 $(qemu_emulator "$machine") -nographic -monitor none -serial none \
    -semihosting-config enable=on,target=native -icount shift=0,align=off,sleep=off "$@" \
    -kernel "$image"
}
