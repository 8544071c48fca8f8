#!/usr/bin/env bash
# core/ stays freestanding: no heap, exceptions, RTTI, hosted containers or headers, and no
# floating point. Comments are stripped first so prose may mention them.
set -u
core="$1"
strip() { sed -e 's://.*$::' "$1"; }
fail=0 pass=0
for f in $(find "$core" -name '*.h' -o -name '*.cpp'); do
  hits=$(strip "$f" | grep -nE '\bnew\b|\bdelete\b|\bmalloc\b|\bfree\(|\bthrow\b|\btry\b|\bcatch\b|dynamic_cast|typeid|std::|\bfloat\b|\bdouble\b|#include *<(iostream|fstream|sstream|vector|string|map|memory|functional|thread|mutex|cmath|cstdio|cstdlib|algorithm)>')
  if [ -n "$hits" ]; then echo "FAILED: $f breaks the freestanding rules:"; echo "$hits"; fail=$((fail + 1)); else pass=$((pass + 1)); fi
done
echo "core_rules: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
