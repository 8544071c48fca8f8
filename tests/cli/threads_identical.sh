#!/usr/bin/env bash
# CTest threads_identical: --threads 1, 2 and 3 write the same bytes. For each scene every file
# a command writes (SVG, spans, G-code, HPGL, a .cut, a step trace) is compared across the
# three counts, and with --threads left out (every core): a haloed random scene (CUT in parts,
# plot, plot --arena in bands, cut), a torus hidden-removed and hatched, an assimp model
# hidden-dashed with outlines (when assimp-testmodels is installed), and a solid in bands
# through `sim` with an arena (each band's CUT in parts). Then --threads 0, -1 and abc are
# refused by name. Fails on any byte that differs, or a bad count taken. The haloed scene and
# the torus are large enough that CUT splits (2^16 pair tests a part, core/include/haloplot/memory/parts.h);
# test cut_parts splits small scenes and bands' rows too.
# Usage: threads_identical.sh HALOPLOT
set -u
tool="$1"
here=$(cd "$(dirname "$0")" && pwd)
# shellcheck source=../support/checks.sh
. "$(cd "$(dirname "$0")" && pwd)/../support/checks.sh"
cd "$work" || exit 1
# shellcheck source=../support/model_files.sh
source "$here/../support/model_files.sh"

# same NAME FILE...: each FILE written for threads 1 as FILE.1, 2 as FILE.2, 3 as FILE.3 and
# every core as FILE.all; all four byte-identical and not empty.
same() {
  local name="$1" f t differ=""
  shift
  for f in "$@"; do
    [ -s "$f.1" ] || { bad "$name: $f not written"; return; }
    for t in 2 3 all; do cmp -s "$f.1" "$f.$t" || differ="$differ $f ($t threads)"; done
  done
  if [ -z "$differ" ]; then ok "$name: $* the same with 1, 2, 3 and every thread"; else
    bad "$name: differs from one thread's:$differ"; fi
}
# run NAME COMMAND...: the command once per thread count, with {} in its arguments replaced by
# the count's suffix and --threads added (left out for "all").
run() {
  local name="$1" t args a
  shift
  for t in 1 2 3 all; do
    args=()
    for a in "$@"; do args+=("${a//\{\}/$t}"); done
    [ "$t" = all ] || args+=(--threads "$t")
    if ! "$tool" "${args[@]}" 2> "err.$t"; then bad "$name: --threads $t failed: $(cat "err.$t")"; fi
  done
}

"$tool" random-scene --edges 20000 --length 0.02 --seed 7 -o random.edges
run haloed plot random.edges --halo 200 -o h.svg.{} --spans h.spans.{} --gcode h.gcode.{} \
  --hpgl h.hpgl.{} --cut h.cut.{}
same "haloed plot" h.svg h.spans h.gcode h.hpgl h.cut
run exact plot random.edges --halo 200 --exact-halo -o x.svg.{} --spans x.spans.{}
same "haloed plot, exact halo (near misses)" x.svg x.spans
"$tool" random-scene --edges 3000 --length 0.03 --seed 7 -o small.edges
run banded plot small.edges --halo 200 --arena 16384 -o b.svg.{} --spans b.spans.{}
same "haloed plot in bands of 16 KB" b.svg b.spans
run cut cut random.edges -o c.cut.{}
same "cut" c.cut

torus_obj 1.5 0.6 160 80 > torus.obj
run torus plot torus.obj --mode hidden-removed --hatch 2 --view 30,25 -o t.svg.{} \
  --spans t.spans.{} --gcode t.gcode.{} --hpgl t.hpgl.{}
same "torus, hidden-removed, hatched" t.svg t.spans t.gcode t.hpgl

spider=/usr/share/assimp/models/OBJ/spider.obj
if [ -r "$spider" ]; then
  run spider plot "$spider" --mode hidden-dashed --outline --view 30,25 -o s.svg.{} \
    --spans s.spans.{} --gcode s.gcode.{}
  same "assimp's spider, hidden-dashed, outlined" s.svg s.spans s.gcode
else
  echo "note: $spider not installed (assimp-testmodels): skipped"
fi

"$tool" demo-scene --cubes 6 -o cubes.obj
printf 'scene cubes.obj\ndrawing hidden-dashed\noutline on\nhatch 2\nview 30,25\narena 49152\n' \
  > banded.job
run "banded solid" sim banded.job -o j.trace.{} --gcode j.gcode.{} --hpgl j.hpgl.{}
same "a solid in bands of 48 KB (sim)" j.trace j.gcode j.hpgl
printf 'scene small.edges\nhalo 200\n' > haloed.job
run "haloed job" sim haloed.job -o k.trace.{} --gcode k.gcode.{}
same "a haloed job (sim)" k.trace k.gcode

for badcount in 0 -1 abc 2.5 257; do
  if "$tool" plot random.edges --halo 200 -o bad.svg --threads "$badcount" 2> err.txt; then
    bad "--threads $badcount taken"
  elif grep -q -- "--threads '$badcount' must be a count of threads from 1 to 256" err.txt; then
    ok "--threads $badcount refused by name"
  else
    bad "--threads $badcount: unclear refusal: $(cat err.txt)"
  fi
done
if "$tool" plot torus.obj --mode all --view 30,25 -o bad.svg --threads 0 2> err.txt ||
   ! grep -q -- "--threads '0'" err.txt; then
  bad "plot of a model took --threads 0"
else
  ok "plot of a model refuses --threads 0"
fi

echo "threads_identical: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
