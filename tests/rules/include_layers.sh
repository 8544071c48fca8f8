#!/usr/bin/env bash
# Layers point one way: a file may include its own folder or a folder below its own, never one
# above. core/'s folders from the bottom:
#   0 status geometry sort hal   1 memory   2 scene view view2d   3 cut   4 draw
#   5 curve solid   6 surface   7 motion   8 trace   9 band   10 job   11 protocol   12 controller
# (folders of one rank do not include each other either). In host_sim/, cli/ is the top: no
# other folder includes it. firmware/ includes nothing from tests/.
# The upward includes the tree still has are listed below, each to be moved away; any other
# fails the rule. `plant` copies the tree with one more upward include (cut/ including job/)
# and must fail.
# Usage: include_layers.sh SOURCE_DIR [plant]
set -u
src="$1"
if [ "${2:-}" = plant ]; then
  copy=$(mktemp -d)
  trap 'rm -rf "$copy"' EXIT
  cp -r "$src/core" "$src/host_sim" "$src/firmware" "$copy/"
  sed -i '1i #include "haloplot/job/job.h"' "$copy/core/cut/grid.cpp"
  src="$copy"
fi
known=(
  "host_sim/pipeline/scene_input.cpp cli" # the command line's Options in the pipeline
  "host_sim/pipeline/scene_input.h cli"
  "host_sim/export/page.h cli"
  "host_sim/io/job_file.cpp cli"
  "firmware/selftest/misaligned_selftest.cpp tests"
)
rank() {
  case "$1" in
    status | geometry | sort | hal) echo 0 ;; memory) echo 1 ;; scene | view | view2d) echo 2 ;;
    cut) echo 3 ;; draw) echo 4 ;; curve | solid) echo 5 ;; surface) echo 6 ;; motion) echo 7 ;;
    trace) echo 8 ;; band) echo 9 ;; job) echo 10 ;; protocol) echo 11 ;; controller) echo 12 ;;
    *) echo "" ;;
  esac
}
is_known() {
  local k
  for k in "${known[@]}"; do [ "$k" = "$1 $2" ] && return 0; done
  return 1
}
fail=0 pass=0 seen=0
check() {  # FILE TARGET_FOLDER ALLOWED(0/1)
  local rel=${1#"$src"/}
  if [ "$3" = 1 ]; then pass=$((pass + 1)); return; fi
  if is_known "$rel" "$2"; then seen=$((seen + 1)); return; fi
  echo "FAILED: $rel includes $2/, a layer above its own"
  fail=$((fail + 1))
}
while IFS= read -r f; do
  folder=$(basename "$(dirname "$f")")
  own=$(rank "$folder")
  [ -n "$own" ] || continue
  # Public headers are included as "haloplot/<folder>/...", internal ones as "<folder>/...".
  for t in $(grep -oE '#include "(haloplot/)?[a-z0-9_]+/' "$f" | sed -E 's|.*"(haloplot/)?||; s|/$||' | sort -u); do
    [ "$t" = "$folder" ] && continue
    r=$(rank "$t")
    check "$f" "$t" "$([ -n "$r" ] && [ "$r" -lt "$own" ] && echo 1 || echo 0)"
  done
done < <(find "$src/core" -name '*.h' -o -name '*.cpp')
while IFS= read -r f; do
  case "$f" in "$src"/host_sim/cli/*) continue ;; esac
  grep -q '#include "cli/' "$f" && check "$f" cli 0 || pass=$((pass + 1))
done < <(find "$src/host_sim" -name '*.h' -o -name '*.cpp')
while IFS= read -r f; do
  grep -qE '#include "(unit|support|reference|tests)/' "$f" && check "$f" tests 0 || pass=$((pass + 1))
done < <(find "$src/firmware" -name '*.h' -o -name '*.cpp')
# A listed include that is gone has been moved: the list must shrink with it.
if [ "$seen" -ne "${#known[@]}" ]; then
  echo "FAILED: $((${#known[@]} - seen)) listed upward include(s) no longer in the tree: drop them from the list"
  fail=$((fail + 1))
fi
echo "include_layers: $pass passed, $fail failed, $seen known upward includes still to move (of ${#known[@]})"
[ "$fail" -eq 0 ]
