# Shared by the CLI test scripts that count conditions: a scratch directory in $work (removed
# on exit; the script changes into it when it is ready), the pass/fail counts, ok, bad MESSAGE,
# and `expect CONDITION NAME`, which evaluates CONDITION quietly and counts it.
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
pass=0 fail=0
ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAILED: $*" >&2; }
expect() { if eval "$1"; then ok; else bad "$2"; fi; }
