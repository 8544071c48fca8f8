#!/usr/bin/env bash
# No function in core/, host_sim/ or firmware/ is longer than 100 lines, so a reader can hold
# each in mind (the long ones are split by step, each step a named function).
# Counted by Universal Ctags: a function's lines run from the line of its name to the line of
# its closing brace, comments and blank lines included; headers (.h) are read as C++.
# Usage: function_length.sh SOURCE_DIR [LIMIT]
set -u
cd "$1"
limit=${2:-100}
if ! ctags --version 2>/dev/null | grep -q 'Universal Ctags'; then
  echo "FAILED: Universal Ctags is needed (apt-get install universal-ctags)"
  echo "function_length: 0 passed, 1 failed"
  exit 1
fi
# Tab-separated: a name such as `operator ()` holds a space.
listing=$(ctags -R --langmap=C++:+.h --languages=C++ --kinds-C++=f --fields=+ne -x \
  --_xformat=$'%N\t%F\t%n\t%e' core host_sim firmware)
total=$(printf '%s\n' "$listing" | awk -F'\t' '$4 != ""' | wc -l)
long=$(printf '%s\n' "$listing" | awk -F'\t' -v limit="$limit" \
  '$4 != "" && $4 - $3 + 1 > limit {printf "%d lines  %s:%s  %s\n", $4 - $3 + 1, $2, $3, $1}' | sort -rn)
if [ -n "$long" ]; then
  printf 'FAILED: over %d lines:\n%s\n' "$limit" "$long"
fi
n_long=$(printf '%s' "$long" | grep -c . || true)
longest=$(printf '%s\n' "$listing" | awk -F'\t' '$4 != "" {n = $4 - $3 + 1; if (n > m) m = n} END {print m + 0}')
echo "functions counted: $total, the longest $longest lines"
echo "function_length: $((total - n_long)) passed, $n_long failed"
[ "$n_long" -eq 0 ]
