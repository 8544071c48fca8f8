#!/usr/bin/env bash
# CTest doc_figures: every figure the README and docs/ quote between <!-- fig:KEY --> and
# <!-- /fig --> must equal what tools/demo_figures.sh gets from the tool today, and the README
# must quote the demo's trace figures. Fix a failure with: bash tools/update_doc_figures.sh
# Usage: doc_figures.sh HALOPLOT SOURCE_DIR
set -u
tool="$1" root="$2"
figures="$(bash "$root/tools/demo_figures.sh" "$tool")" || { echo "FAILED: tools/demo_figures.sh"; exit 1; }
cd "$root"
fail=0 checked=0
while IFS=$'\t' read -r where key quoted; do
  want="$(printf '%s\n' "$figures" | sed -n "s/^$key=//p")"
  checked=$((checked + 1))
  if [ -z "$want" ]; then
    echo "FAILED: $where: fig:$key is no figure tools/demo_figures.sh prints"; fail=1
  elif [ "$quoted" != "$want" ]; then
    echo "FAILED: $where: fig:$key says '$quoted', the tool gives '$want'"; fail=1
  fi
done < <(perl -ne 'while (/<!-- fig:([A-Za-z0-9_]+) -->(.*?)<!-- \/fig -->/g) { print "$ARGV:$.\t$1\t$2\n" } close ARGV if eof' README.md docs/*.md docs/reports/*.md)
for key in demo_edges trace_steps trace_bytes; do
  grep -q "<!-- fig:$key -->" README.md || { echo "FAILED: README.md quotes no fig:$key"; fail=1; }
done
echo "doc_figures: $checked quoted figures checked"
[ "$fail" -eq 0 ]
