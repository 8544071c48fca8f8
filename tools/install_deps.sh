#!/usr/bin/env bash
# Installs, on a fresh Debian machine, whatever of the build and test tools is missing.
# Usage: tools/install_deps.sh [demo|test]
set -euo pipefail
want_demo=(cmake g++ make rsvg-convert)
want_test=(cmake g++ make clang++ clang-format ctags valgrind arm-none-eabi-gcc arm-none-eabi-g++ qemu-system-arm
           riscv64-unknown-elf-g++ qemu-system-riscv32)
declare -A package=(
  [cmake]=cmake [g++]=g++ [make]=make [clang++]=clang [clang-format]=clang-format [ctags]=universal-ctags [valgrind]=valgrind
  [rsvg-convert]=librsvg2-bin
  [arm-none-eabi-gcc]=gcc-arm-none-eabi [arm-none-eabi-g++]=gcc-arm-none-eabi
  [qemu-system-arm]=qemu-system-arm
  [riscv64-unknown-elf-g++]=gcc-riscv64-unknown-elf [qemu-system-riscv32]=qemu-system-misc
)
case "${1:-test}" in
  demo) tools=("${want_demo[@]}") ;;
  test) tools=("${want_test[@]}") ;;
  *) echo "usage: $0 [demo|test]" >&2; exit 2 ;;
esac
missing=()
for t in "${tools[@]}"; do command -v "$t" >/dev/null 2>&1 || missing+=("${package[$t]}"); done
# The C++ runtime headers for the cross compiler ship separately from the compiler.
if [ "${1:-test}" = test ]; then
  # cross C++ headers; libFuzzer; real OBJ files nobody here wrote (the real_meshes test)
  for pkg in libstdc++-arm-none-eabi-newlib libclang-rt-14-dev assimp-testmodels; do
    dpkg -s "$pkg" >/dev/null 2>&1 || missing+=("$pkg")
  done
fi
[ ${#missing[@]} -eq 0 ] && exit 0
mapfile -t missing < <(printf '%s\n' "${missing[@]}" | sort -u)
echo "installing: ${missing[*]}"
if [ "$(id -u)" -ne 0 ]; then
  echo "not root: run 'apt-get install ${missing[*]}' as root, then retry" >&2
  exit 1
fi
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
