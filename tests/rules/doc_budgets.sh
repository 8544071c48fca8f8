#!/usr/bin/env bash
# The flash and RAM figures the docs quote are the built images' and the boards' budgets:
# docs/firmware.md's `firmware-sizes` table must be what tools/firmware_sizes.sh prints now
# (budgets from each board.cmake, sizes from the images as the size gate sums them), so a
# change that grows an image or moves a budget updates the docs with it.
# Usage: doc_budgets.sh SOURCE_DIR
set -u
root="$1"
if ! want=$(bash "$root/tools/firmware_sizes.sh" "$root"); then
  echo "FAILED: tools/firmware_sizes.sh could not measure the images"
  echo "doc_budgets: 0 passed, 1 failed"
  exit 1
fi
have=$(sed -n '/<!-- firmware-sizes:/,/<!-- \/firmware-sizes -->/p' "$root/docs/firmware.md" | sed '1d;$d')
if [ "$have" = "$want" ]; then
  echo "$want"
  echo "doc_budgets: 1 passed, 0 failed"
  exit 0
fi
echo "FAILED: docs/firmware.md quotes other sizes than the images have; run"
echo "  bash tools/firmware_sizes.sh --write"
diff <(echo "$have") <(echo "$want")
echo "doc_budgets: 0 passed, 1 failed"
exit 1
