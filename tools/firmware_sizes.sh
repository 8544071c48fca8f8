#!/usr/bin/env bash
# The controller images' flash and RAM against their budgets, as one table: the budgets read
# from each board's board.cmake (the one place they are set), the sizes summed from the built
# images as the size gate sums them (firmware/check_image.cmake: flash = .vectors .text
# .ARM.exidx .init_array .data; RAM = .data .bss .ccm), and the lean programs' .text
# (firmware/lean: one plot, unbanded, in bands, a solid in bands). docs/firmware.md quotes both
# tables between its `firmware-sizes` markers; test doc_budgets checks that they are this output.
# Usage: tools/firmware_sizes.sh [ROOT]           print the table (the firmware presets built)
#        tools/firmware_sizes.sh --write [ROOT]   put it into docs/firmware.md
set -euo pipefail
write=0
if [ "${1:-}" = --write ]; then
  write=1
  shift
fi
root="$(cd "${1:-$(dirname "$0")/..}" && pwd)"

budget() {  # BOARD NAME: the value board.cmake sets
  sed -n "s/^set(HALOPLOT_BOARD_$2 \([0-9]*\))/\1/p" "$root/firmware/boards/$1/board.cmake"
}
sizes() {  # ELF: "flash ram"
  arm-none-eabi-size -A "$1" | awk '
    $1 ~ /^\.(vectors|text|ARM\.exidx|init_array|data)$/ { flash += $2 }
    $1 ~ /^\.(data|bss|ccm)$/ { ram += $2 }
    END { print flash + 0, ram + 0 }'
}
kb() { echo "$(($1 / 1024)) KB"; }

table() {
  echo "| board | image | flash, bytes | flash budget | RAM, bytes | RAM budget | job arena |"
  echo "|---|---|---:|---:|---:|---:|---:|"
  for pair in stm32f405:firmware mps2_an385:firmware-mps2; do
    local board=${pair%%:*} preset=${pair#*:}
    local elf="$root/build/$preset/firmware/fw_plotter.elf"
    if [ ! -f "$elf" ]; then
      echo "no $elf: build the $preset preset first (cmake --build --preset $preset)" >&2
      return 1
    fi
    local flash ram
    read -r flash ram < <(sizes "$elf")
    printf '| %s | `fw_plotter` | %s | %s | %s | %s | %s |\n' "$board" "$flash" \
      "$(kb "$(budget "$board" FLASH_BUDGET)")" "$ram" "$(kb "$(budget "$board" RAM_BUDGET)")" \
      "$(budget "$board" ARENA_KB) KB"
  done
}

# What one kind of plot costs an image of its own (firmware/lean/lean_link.cpp, test lean_link):
# .text of the smallest programs that plot the same three edges through the step tick.
lean() {
  echo
  echo "The same plot in the smallest image (\`firmware/lean\`, \`.text\` bytes; test \`lean_link\`):"
  echo
  echo "| board | haloed (\`job_prepare\`) | haloed in bands (\`begin\`) | a solid in bands (\`begin_solid\`) |"
  echo "|---|---:|---:|---:|"
  for pair in stm32f405:firmware mps2_an385:firmware-mps2; do
    local board=${pair%%:*} dir="$root/build/${pair#*:}/firmware"
    local h b s
    h=$(text "$dir/fw_lean_haloed.elf") && b=$(text "$dir/fw_lean_bands.elf") &&
      s=$(text "$dir/fw_lean_solid_bands.elf") || return 1
    printf '| %s | %s | %s (%s) | %s (%s) |\n' "$board" "$h" "$b" "$(ratio "$b" "$h")" "$s" \
      "$(ratio "$s" "$h")"
  done
}
text() {  # ELF: its .text bytes
  [ -f "$1" ] || { echo "no $1: build the firmware presets first" >&2; return 1; }
  arm-none-eabi-size -A "$1" | awk '$1 == ".text" { print $2 }'
}
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.2fx", a / b }'; }

out=$(table && lean)
if [ "$write" -eq 0 ]; then
  echo "$out"
  exit 0
fi
doc="$root/docs/firmware.md"
python3 - "$doc" "$out" <<'EOF'
import sys
path, table = sys.argv[1], sys.argv[2]
text = open(path).read()
begin, end = "<!-- firmware-sizes: tools/firmware_sizes.sh --write -->\n", "<!-- /firmware-sizes -->"
a = text.index(begin) + len(begin)
b = text.index(end, a)
open(path, "w").write(text[:a] + table + "\n" + text[b:])
EOF
echo "wrote the table into docs/firmware.md"
