#!/usr/bin/env bash
# Every C++ source matches the committed .clang-format.
set -u
cd "$1"
files=$(find core hal host_sim firmware tests -name '*.cpp' -o -name '*.h')
bad=0 good=0
for f in $files; do
  if clang-format --dry-run -Werror "$f" >/dev/null 2>&1; then good=$((good + 1)); else bad=$((bad + 1)); echo "FAILED: $f is not clang-formatted"; fi
done
echo "format: $good passed, $bad failed"
[ "$bad" -eq 0 ]
