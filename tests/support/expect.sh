# Shared by the CLI test scripts that run many small checks: a scratch directory (the current
# directory from here on, removed on exit), the pass/fail counts, and `expect CMD NAME`, which
# runs CMD (eval'd, output to out.txt) and counts it: a pass prints its last line, a failure
# all of it. Source it after the script has read its own arguments and paths.
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
pass=0 fail=0
expect() {
  if eval "$1" > out.txt 2>&1; then
    pass=$((pass + 1))
    echo "ok: $2: $(tail -1 out.txt)"
  else
    fail=$((fail + 1))
    echo "FAILED: $2: $(cat out.txt)"
  fi
}
