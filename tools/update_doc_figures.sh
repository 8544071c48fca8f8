#!/usr/bin/env bash
# Rewrites every figure quoted between <!-- fig:KEY --> and <!-- /fig --> in README.md and
# docs/*.md and docs/reports/*.md with what tools/demo_figures.sh prints today (the CTest doc_figures checks them).
# Usage: tools/update_doc_figures.sh [HALOPLOT]   (default build/host/host_sim/haloplot)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
figures="$(bash "$root/tools/demo_figures.sh" "$@")"
cd "$root"
FIGURES="$figures" perl -pi -e '
  BEGIN { %f = map { /^([^=]+)=(.*)$/ ? ($1, $2) : () } split /\n/, $ENV{FIGURES} }
  s{(<!-- fig:([A-Za-z0-9_]+) -->)(.*?)(<!-- /fig -->)}{exists $f{$2} ? "$1$f{$2}$4" : "$1$3$4"}ge;
' README.md docs/*.md docs/reports/*.md
printf '%s\n' "$figures"
git --no-pager diff --stat -- README.md docs/ || true
