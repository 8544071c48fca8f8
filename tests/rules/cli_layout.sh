#!/usr/bin/env bash
# The haloplot tool stays one command per file: host_sim/cli/main.cpp holds the start-up and
# the table of commands, at most 250 lines, and every cmd_ function is declared in
# host_sim/cli/commands.h alone, so a reader finds each command from one header and no file
# reaches a command through a declaration of its own. Comments are stripped first so prose may
# name a command; a declaration is one line, `TYPE cmd_NAME(...);`.
# Usage: cli_layout.sh SOURCE_DIR [long|declared]
#   long, declared: the check run on a copy of host_sim with that violation planted (main.cpp
#   padded past the limit, or cmd_plot declared in cmd_sim.cpp); it must fail (WILL_FAIL).
set -u
src="$1"
limit=250
if [ $# -ge 2 ]; then
  work=$(mktemp -d)
  trap 'rm -rf "$work"' EXIT
  cp -r "$src/host_sim" "$work/host_sim"
  case "$2" in
    long) for _ in $(seq $((limit + 1))); do echo "// padding" >> "$work/host_sim/cli/main.cpp"; done ;;
    declared) echo "int cmd_plot(int argc, char** argv);" >> "$work/host_sim/cli/cmd_sim.cpp" ;;
    *) echo "unknown plant '$2'"; exit 2 ;;
  esac
  src="$work"
fi
cd "$src"
pass=0 fail=0
lines=$(wc -l < host_sim/cli/main.cpp)
if [ "$lines" -gt "$limit" ]; then
  echo "FAILED: host_sim/cli/main.cpp is $lines lines, over $limit: a command or a helper belongs in its own file"
  fail=$((fail + 1))
else
  pass=$((pass + 1))
fi
decl='^[[:space:]]*([A-Za-z_][A-Za-z_0-9:<>]*[[:space:]]+)+[*&]*cmd_[A-Za-z0-9_]+[[:space:]]*\([^;{]*\)[[:space:]]*;'
while IFS= read -r f; do
  [ "$f" = host_sim/cli/commands.h ] && continue
  hits=$(sed -e 's://.*$::' "$f" | grep -nE "$decl" | grep -vE '^[0-9]+:[[:space:]]*return\b')
  if [ -n "$hits" ]; then
    echo "FAILED: $f declares a command outside host_sim/cli/commands.h:"
    echo "$hits"
    fail=$((fail + 1))
  else
    pass=$((pass + 1))
  fi
done < <(find host_sim -name '*.h' -o -name '*.cpp' | sort)
echo "cli_layout: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
