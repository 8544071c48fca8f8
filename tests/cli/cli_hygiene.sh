#!/usr/bin/env bash
# What a new user runs into on the command line, each refused or accepted as a user expects:
# an image format -o cannot write is refused by name; options the mode or the input has no
# use for are refused by name, never ignored; --opt=value works for every option; every
# command's --help lists every option its parser takes; "cannot open" says why.
set -u
tool="$1"
work=$(mktemp -d)
trap 'chmod -R u+rwx "$work"; rm -rf "$work"' EXIT
pass=0 fail=0
ok() { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAILED: $*" >&2; }
expect() { if eval "$1"; then ok; else bad "$2"; fi; }
# refused CMD... : non-zero exit, the message names $want, and no $out was left behind.
refused() {
  local want="$1" out="$2"
  shift 2
  "$tool" "$@" 2> err.txt
  local rc=$?
  expect '[ $rc -ne 0 ] && grep -qF -- "$want" err.txt && [ ! -e "$out" ]' \
    "'$*' is refused naming '$want' (rc $rc): $(head -c 300 err.txt)"
}

cd "$work"
"$tool" demo-scene --cubes 3 -o scene.edges
"$tool" demo-scene --cubes 2 -o cubes.obj

# -o with an image format the tool does not write: refused, by the extension.
for ext in png PDF jpg eps; do
  refused ".$ext" "x.$ext" plot scene.edges --halo 5 -o "x.$ext"
done
refused ".png" x.png plot cubes.obj --mode hidden-removed -o x.png
refused "--gcode" x.gcode plot scene.edges --halo 5 -o x.gcode
"$tool" cut scene.edges -o scene.cut
refused ".pdf" y.pdf draw scene.cut --halo 5 -o y.pdf
"$tool" plot scene.edges --halo 5 -o fine.svg
expect '[ $? -eq 0 ] && grep -q "<svg" fine.svg' "-o fine.svg still writes an SVG"

# Options the chosen mode or input cannot use.
refused "--hatch" a.svg plot cubes.obj --mode all --hatch 2 -o a.svg
refused "--dash" a.svg plot cubes.obj --mode hidden-removed --dash 2,1 -o a.svg
refused "--dash" a.svg plot cubes.obj --mode all --dash 2,1 -o a.svg
for opt in "--view 30,25" "--perspective 1000" "--up z" "--crease 10" "--dump-edges d.edges"; do
  refused "${opt%% *}" a.svg plot scene.edges --halo 5 $opt -o a.svg
done
printf 'scene scene.edges\nhalo 5\nview 30,25\n' > view.job
refused "view.job:3: view is for a model scene" v.trace sim view.job -o v.trace
"$tool" plot cubes.obj --mode hidden-dashed --dash 2,1 --hatch 2 -o ok.svg
expect '[ $? -eq 0 ]' "--dash and --hatch still work with hidden-dashed"

# --opt=value is --opt value, for every valued option of plot (same bytes).
"$tool" plot cubes.obj --mode hidden-dashed --view 30,25 --dash 1,0.5 -o spaced.svg
"$tool" plot cubes.obj --mode=hidden-dashed --view=30,25 --dash=1,0.5 -o eq.svg
expect 'cmp -s spaced.svg eq.svg' "--opt=value draws what --opt value draws"
"$tool" plot scene.edges --halo=5 --steps-per-mm=40 -o h1.svg
"$tool" plot scene.edges --halo 5 --steps-per-mm 40 -o h2.svg
expect 'cmp -s h1.svg h2.svg' "--halo=5 is --halo 5"
"$tool" plot scene.edges --halo 5 --stats=yes -o h3.svg 2> err.txt
rc=$?
expect '[ $rc -ne 0 ] && grep -q "takes no value" err.txt' "a flag given a value is refused: $(cat err.txt)"

# Every command's --help lists every option its parser knows (the list an unknown option
# prints), so nothing the tool takes is missing from its help.
for cmd in demo-scene random-scene cut draw plot sim replay send view2d; do
  "$tool" "$cmd" --help > help.txt
  "$tool" "$cmd" x --zzzz-not-an-option -o y 2> err.txt
  known=$(sed -n 's/^known options: //p' err.txt)
  expect '[ -n "$known" ]' "$cmd: an unknown option lists the known ones: $(cat err.txt)"
  for opt in $known; do
    expect 'grep -qe "$opt\\b" help.txt' "$cmd --help lists $opt"
  done
done
for opt in --pause-at --resume-at; do
  "$tool" sim --help | grep -q -- "$opt"
  expect '[ $? -eq 0 ]' "sim --help lists $opt"
done
for opt in --stop-after --resume; do
  "$tool" send --help | grep -q -- "$opt"
  expect '[ $? -eq 0 ]' "send --help lists $opt"
done

# "cannot open" says why, for every kind of input.
mkdir adir.edges adir.obj adir.job adir.cut adir.trace
printf '1 2 3 4 5 6\n' > locked.edges
chmod 000 locked.edges
refused "no such file" a.svg plot missing.edges --halo 5 -o a.svg
refused "a directory" a.svg plot adir.edges --halo 5 -o a.svg
refused "a directory" a.svg plot adir.obj --mode hidden-removed -o a.svg
refused "a directory" t.trace sim adir.job -o t.trace
refused "a directory" a.svg draw adir.cut --halo 5 -o a.svg
refused "a directory" a.svg replay adir.trace -o a.svg
refused "no such file" a.svg replay missing.trace -o a.svg
if [ "$(id -u)" != 0 ]; then  # root reads a mode-000 file anyway
  refused "permission denied" a.svg plot locked.edges --halo 5 -o a.svg
fi
for f in adir.edges adir.obj; do
  "$tool" plot "$f" --halo 5 -o a.svg 2> err.txt
  expect '! grep -q "read error" err.txt' "a directory is not a read error: $(cat err.txt)"
done

# A model with neither --mode nor --halo: the message offers both ways to draw it (it asked
# for --halo alone, though a model's usual drawing is its hidden lines); an edge scene has
# only --halo.
refused "--mode all|hidden-removed|hidden-dashed" m.svg plot cubes.obj -o m.svg
expect 'grep -qF -- "--halo W" err.txt' "the model's message names --halo too: $(cat err.txt)"
refused "--halo W (steps) is required" e.svg plot scene.edges -o e.svg

# G-code alone needs no SVG: -o may be left out with --gcode (it was "missing -o OUTPUT").
mkdir gonly
(cd gonly && "$tool" plot ../cubes.obj --mode hidden-removed --gcode only.gcode) 2> err.txt
expect '[ $? -eq 0 ] && grep -q "^G[01] " gonly/only.gcode && [ "$(ls gonly)" = only.gcode ]' \
  "plot --gcode without -o writes the G-code and nothing else: $(cat err.txt)"
"$tool" plot cubes.obj --mode hidden-removed -o with.svg --gcode with.gcode 2> /dev/null
expect 'cmp -s gonly/only.gcode with.gcode' "the G-code is the same with and without -o"
refused "missing -o OUTPUT" none.svg plot cubes.obj --mode hidden-removed

# A cube as a triangle soup (each face its own corners, as some exporters write OBJ): welded by
# default, a closed surface; with --weld off an open one; with its corners 0.01 apart (more
# than its rounding) the message names the --weld that joins them (one that closes every open
# side: at least the 0.02 two copies of a corner lie apart, below 1/8 of a side).
for f in "0 0 0 1 0 0 1 1 0" "0 0 0 1 1 0 0 1 0" "0 0 1 1 1 1 1 0 1" "0 0 1 0 1 1 1 1 1" \
  "0 0 0 1 0 1 1 0 0" "0 0 0 0 0 1 1 0 1" "0 1 0 1 1 0 1 1 1" "0 1 0 1 1 1 0 1 1" \
  "0 0 0 0 1 0 0 1 1" "0 0 0 0 1 1 0 0 1" "1 0 0 1 0 1 1 1 1" "1 0 0 1 1 1 1 1 0"; do
  set -- $f
  printf 'v %s %s %s\nv %s %s %s\nv %s %s %s\n' "$@"
done > soup.obj
awk '/^v/ { n++ } END { for (i = 1; i <= n; i += 3) print "f", i, i + 1, i + 2 }' soup.obj >> soup.obj
"$tool" plot soup.obj --mode hidden-removed -o soup.svg 2> err.txt
expect '[ $? -eq 0 ] && ! grep -q "shell" err.txt' "the default weld closes the soup: $(cat err.txt)"
"$tool" plot soup.obj --mode hidden-removed --weld off -o soup.svg 2> err.txt
expect '[ $? -eq 0 ] && grep -q "soup.obj: all 12 shells are open; faces hide from both sides" err.txt && ! grep -qF -- "--weld" err.txt' \
  "--weld off leaves the soup open, no hint: $(cat err.txt)"
awk '/^v/ { printf "v %.6f %s %s\n", $2 + (NR % 3) * 0.01, $3, $4; next } { print }' soup.obj > far.obj
"$tool" plot far.obj --mode hidden-removed -o far.svg 2> err.txt
eps=$(grep -o -- "--weld [0-9.e-]* would close all 36 open sides" err.txt | awk '{ print $2 }')
expect '[ -n "$eps" ] && awk -v e="$eps" "BEGIN { exit !(e >= 0.02 && e < 0.125) }"' "corners 0.01 apart: the message names a --weld in [0.02, 0.125) closing every open side: $(cat err.txt)"
"$tool" plot far.obj --mode hidden-removed --weld "${eps:-0.025}" -o far.svg 2> err.txt
expect '[ $? -eq 0 ] && ! grep -q "shell" err.txt' "--weld ${eps:-?} closes it: $(cat err.txt)"

# A cut-short binary STL whose header begins with 'solid' (as many exporters write it): the
# message must not say it does not.
{ printf 'solid exported'; head -c 36 /dev/zero; } > short.stl
refused "begins with 'solid' but holds a NUL byte" s.svg plot short.stl --mode hidden-removed -o s.svg
head -c 50 /dev/zero > zeros.stl
refused "does not begin with 'solid'" s.svg plot zeros.stl --mode hidden-removed -o s.svg

# An OBJ file longer than the 64 KB head that says what it is is parsed from the file, never
# held whole (io/mesh_file.cpp): the same drawing as its text read whole (a head of blanks
# decides nothing, so that copy is), and content that is not OBJ is still refused by name.
"$tool" demo-scene --cubes 40 -o big.obj
{ head -c 70000 /dev/zero | tr '\0' '\n'; cat big.obj; } > blank_head.obj
"$tool" plot big.obj --mode hidden-removed -o big.svg --spans big.spans
"$tool" plot blank_head.obj --mode hidden-removed -o blank.svg --spans blank.spans
expect 'cmp -s big.spans blank.spans && [ -s big.spans ]' "a long OBJ streamed draws as read whole"
{ printf 'ply\nformat ascii 1.0\n'; head -c 70000 /dev/zero | tr '\0' ' '; } > ply.obj
refused "not a Wavefront OBJ file: it is a PLY file" p.svg plot ply.obj --mode hidden-removed -o p.svg
{ head -c 80 /dev/zero; printf '\x78\x05\x00\x00'; head -c 70000 /dev/zero; } > stl.obj
refused "not a Wavefront OBJ file: it is a binary STL file" p.svg plot stl.obj --mode hidden-removed \
  -o p.svg

# An output that cannot be written is said before any work: one line, naming the path and why,
# whichever output it is and in whichever command, and nothing else is written.
refused "nodir/x.svg: cannot write there (no folder 'nodir/')" fine2.svg \
  plot cubes.obj --mode hidden-removed -o fine2.svg --gcode nodir/x.svg
expect '[ "$(wc -l < err.txt)" -eq 1 ]' "the missing folder is the only line: $(cat err.txt)"
refused "nodir/p.gcode: cannot write there" x.svg plot scene.edges --halo 5 -o x.svg --gcode=nodir/p.gcode
printf 'scene scene.edges\nhalo 5\n' > ok.job
refused "nodir/t.trace: cannot write there" nodir/t.trace sim ok.job -o nodir/t.trace
mkdir ro && chmod a-w ro
if [ "$(id -u)" != 0 ]; then
  refused "ro/x.svg: cannot write there (folder 'ro/' is not writable)" ro/x.svg \
    plot scene.edges --halo 5 -o ro/x.svg
fi

# Settings that would drop every dash, or a pen setting out of range, refused before the work.
refused "a dash is shorter than the minimum stroke" dd.svg plot cubes.obj --mode hidden-dashed \
  --dash 0.8,0.5 --min-stroke 1 -o dd.svg
refused "--pen-dwell '0.0004' must be seconds" pd.gcode plot cubes.obj --mode hidden-removed \
  --gcode pd.gcode --pen-dwell 0.0004

# A model without its extension is read as an .edges scene: the refusal says so.
printf 'solid part\n  facet normal 0 0 1\n' > part
refused "a file not named .edges is read as an .edges scene" pp.svg plot part --halo 5 -o pp.svg

echo "cli_hygiene: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
