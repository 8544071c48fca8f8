#!/usr/bin/env bash
# End-to-end checks of the haloplot tool: exit codes, error messages naming file and line,
# nothing half-written on failure, cut + draw equal to plot, and re-drawing from a .cut file.
set -u
tool="$1"
here="$(cd "$(dirname "$0")" && pwd)"
# shellcheck source=../support/checks.sh
. "$(cd "$(dirname "$0")" && pwd)/../support/checks.sh"

cd "$work"
"$tool" demo-scene --cubes 6 -o scene.edges
expect '[ "$(grep -vc "^#" scene.edges)" = 432 ]' "6 x 6 cubes give 432 edges"

# Malformed input: non-zero exit, file:line in the message, no output left behind.
printf '# ok\n1 2 3 4 5 6\n1 2 3 4 five 6\n' > broken.edges
"$tool" plot broken.edges --halo 5 -o out.svg 2> err.txt
expect '[ $? -ne 0 ]' "malformed input must fail"
expect 'grep -q "broken.edges:3: field 5 .five." err.txt' "error names file and line: $(cat err.txt)"
expect '[ ! -e out.svg ] && [ ! -e out.svg.tmp ]' "no output after a failure"
"$tool" plot scene.edges -o out.svg 2> err.txt
expect '[ $? -ne 0 ] && grep -q -- "--halo" err.txt' "missing --halo is an error"
"$tool" plot scene.edges --halo 5 --frobnicate -o out.svg 2> err.txt
expect '[ $? -ne 0 ] && grep -q "unknown option --frobnicate" err.txt' "unknown options are errors"
"$tool" cut scene.edges --cover diagonal -o x.cut 2> err.txt
expect '[ $? -ne 0 ] && [ ! -e x.cut ]' "bad --cover is an error"

# cut then draw gives exactly what plot gives, in both halo modes.
"$tool" plot scene.edges --halo 60 -o a.svg --spans a.spans --cut a.cut --stats 2> stats.txt
expect '[ $? -eq 0 ]' "plot succeeds"
for key in edges crossings grid cell_pairs pairs_tested cut_ms draw_ms; do
  expect "grep -q '^$key=' stats.txt" "--stats prints $key"
done
"$tool" cut scene.edges -o b.cut && "$tool" draw b.cut --halo 60 -o b.svg --spans b.spans
expect 'cmp -s a.spans b.spans' "cut + draw equals plot (paper halo)"
expect 'cmp -s a.cut b.cut' "the .cut file is deterministic"
"$tool" plot scene.edges --halo 60 --exact-halo --reach 60 -o c.svg --spans c.spans
"$tool" cut scene.edges --reach 60 -o c.cut && "$tool" draw c.cut --halo 60 --exact-halo -o d.svg --spans d.spans
expect 'cmp -s c.spans d.spans' "cut + draw equals plot (exact halo)"
# Re-drawing with another width from the same .cut: a different picture, no CUT.
"$tool" draw b.cut --halo 200 -o e.svg --spans e.spans --stats 2> stats2.txt
expect '! cmp -s a.spans e.spans' "another halo width draws differently"
expect 'grep -q "^cut_ran=0" stats2.txt' "draw reports that CUT did not run"
# Exact halo beyond the reach CUT used: a warning that says what to do.
"$tool" draw b.cut --halo 60 --exact-halo -o f.svg 2> warn.txt
expect 'grep -q "rerun cut with --reach 60" warn.txt' "reach warning"
expect 'grep -q "<svg" a.svg && grep -q "</svg>" a.svg' "SVG is complete"
# view2d: the 2-D visibility tool and its input errors.
printf '0 0\n0 10\n10 10\n10 0\n' > square.txt
"$tool" view2d square.txt --from -5,5 -o sq.svg --spans sq.spans --stats > sq.stats
expect '[ $? -eq 0 ] && grep -q "<circle" sq.svg && grep -q "^configuration=free exterior" sq.stats' "view2d draws and reports"
expect '[ "$(grep -c "^s 0 0 0 0 10$" sq.spans)" = 1 ] && [ "$(grep -c "^s " sq.spans)" = 1 ]' "from the left only the left edge, whole: $(cat sq.spans)"
"$tool" view2d square.txt --from -5,5 -o sq2.svg --trace sq.trace
expect '[ $? -eq 0 ] && grep -q "^end " sq.trace' "view2d plots its visible parts to a step trace"
"$tool" replay sq.trace -o sq_replay.svg --stats > sq_replay.txt 2>&1
expect '[ $? -eq 0 ]' "the view2d trace replays"
printf '0 0\n10 10\n# a comment\n10 zero\n0 10\n' > broken.txt
"$tool" view2d broken.txt --from -5,5 -o b2.svg 2> err.txt
rc=$?
expect '[ $rc -ne 0 ] && grep -q "broken.txt:4: field 2 .zero." err.txt && [ ! -e b2.svg ]' "view2d names file and line: $(cat err.txt)"
printf '0 0\n10 10\n10 0\n0 10\n' > bow.txt
"$tool" view2d bow.txt --from -5,5 -o b3.svg 2> err.txt
rc=$?
expect '[ $rc -ne 0 ] && grep -q "not simple: edges" err.txt' "self-intersection is named: $(cat err.txt)"
"$tool" view2d square.txt --from 0,5 -o b4.svg 2> err.txt
rc=$?
expect '[ $rc -ne 0 ] && grep -q "lies on the polygon" err.txt' "E on the polygon is an error: $(cat err.txt)"
# OBJ in: projected with the view, dumped as .edges, the same drawing as plotting the dump.
printf 'v 0 0 0\nv 4 0 0\nv 4 4 0\nv 0 4 0\nv 0 0 4\nv 4 0 4\nv 4 4 4\nv 0 4 4\nf 1 2 3 4\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n' > cube.obj
"$tool" plot cube.obj --view 30,40 --halo 40 -o obj.svg --spans obj.spans --dump-edges obj.edges
rc=$?
expect '[ $rc -eq 0 ] && [ "$(grep -vc "^#" obj.edges)" = 12 ]' "an OBJ cube plots and dumps its 12 edges"
"$tool" plot obj.edges --halo 40 -o obj2.svg --spans obj2.spans
expect 'cmp -s obj.spans obj2.spans' "plotting the dumped edges gives the same spans"
"$tool" plot cube.obj --view 30,40 --perspective 2 --halo 40 -o objp.svg 2> err.txt
rc=$?
expect '[ $rc -ne 0 ] && grep -q "eye plane" err.txt && [ ! -e objp.svg ]' "an eye inside the model is refused: $(cat err.txt)"
"$tool" plot cube.obj --view 30,forty --halo 40 -o objv.svg 2> err.txt
rc=$?
expect '[ $rc -ne 0 ] && grep -q -- "--view" err.txt' "a bad --view is named: $(cat err.txt)"
# Sub-step units: decided 16 times finer, drawn in steps. The dump and the CUTSET say their
# units ('# substep 4'), so plotting the dump and drawing the CUTSET give the same spans, and
# the spans are in steps (inside the 20,400-step plot area, not 16 times beyond it).
"$tool" plot cube.obj --substep 4 --halo 40 -o u.svg --spans u.spans --dump-edges u.edges --cut u.cut
rc=$?
expect '[ $rc -eq 0 ] && grep -q "^# substep 4$" u.edges && grep -q "^# substep 4$" u.cut' "sub-step files say their units"
"$tool" plot u.edges --halo 40 -o u2.svg --spans u2.spans && "$tool" draw u.cut --halo 40 -o u3.svg --spans u3.spans
expect 'cmp -s u.spans u2.spans && cmp -s u.spans u3.spans' "the dump and the CUTSET in units draw the same spans"
expect '[ "$(awk '"'"'$1 == "s" && ($3 > 20400 || $4 > 20400 || $5 > 20400 || $6 > 20400)'"'"' u.spans | wc -l)" = 0 ] && grep -q "^s " u.spans' "sub-step spans are in steps"
"$tool" plot cube.obj --substep 6 --halo 40 -o u4.svg 2> err.txt
rc=$?
expect '[ $rc -ne 0 ] && grep -q "substep 6: the plot area times 2^6" err.txt && [ ! -e u4.svg ]' "too many sub-step bits for the plot area are named: $(cat err.txt)"
"$tool" plot u.edges --substep 2 --halo 40 -o u5.svg 2> err.txt
rc=$?
expect '[ $rc -ne 0 ] && grep -q "substep is for .obj" err.txt' "--substep on an .edges file is refused: $(cat err.txt)"
{ echo "# substep nine"; grep -v "^#" u.edges; } > badunits.edges
"$tool" plot badunits.edges --halo 40 -o u6.svg 2> err.txt
rc=$?
expect '[ $rc -ne 0 ] && grep -q "badunits.edges.*substep" err.txt' "a bad units header is named: $(cat err.txt)"
printf 'scene cube.obj\ndrawing haloed\nhalo 40\nsubstep 9\n' > badunits.job
"$tool" sim badunits.job -o u7.trace 2> err.txt
rc=$?
expect '[ $rc -ne 0 ] && grep -q "badunits.job:4" err.txt && [ ! -e u7.trace ]' "a bad substep in a job is named with its line: $(cat err.txt)"

# Hidden-line modes from a solid model (the cube above has its bottom face wound the wrong way:
# the orientation repair turns it to agree with its shell, so it draws as the fixed cube, by QI).
sed 's/^f 1 2 3 4$/f 4 3 2 1/' cube.obj > good.obj
for mode in all hidden-removed hidden-dashed; do
  "$tool" plot good.obj --view 30,25 --mode $mode --outline -o m_$mode.svg --spans m_$mode.spans --stats 2> m_$mode.txt
  rc=$?
  expect '[ $rc -eq 0 ] && grep -q "^method=qi" m_$mode.txt && grep -q "^rule_wedge=" m_$mode.txt' "--mode $mode plots a closed cube by QI: $(cat m_$mode.txt)"
  expect '[ "$(grep "^s " m_$mode.spans | awk "NF != 7" | wc -l)" = 0 ] && grep -q "^o " m_$mode.spans' "--mode $mode writes s EDGE X0 Y0 X1 Y1 QI and the outline pass"
done
expect '[ "$(grep -c "^s .* 0$" m_hidden-removed.spans)" = 9 ]' "a cube shows 9 visible edges"
expect '[ "$(grep -c "^s " m_all.spans)" = 12 ]' "all: the 12 edges whole"
expect '[ "$(grep -c "^s .* 1$" m_hidden-dashed.spans)" -gt 3 ]' "dashed: the 3 hidden edges cut into dashes"
"$tool" plot good.obj --view 30,25 --mode hidden-removed -o good_hr.svg --spans good_hr.spans
"$tool" plot cube.obj --view 30,25 --mode hidden-removed -o bad_orient.svg --spans bad_orient.spans --stats 2> err.txt
rc=$?
# The same strokes (each with its ends in order; the edge numbers follow each file's face order).
strokes() { awk '$1 == "s" { if ($3 > $5 || ($3 == $5 && $4 > $6)) print $5, $6, $3, $4; else print $3, $4, $5, $6 }' "$1" | sort; }
expect '[ $rc -eq 0 ] && grep -q "^method=qi" err.txt && [ "$(strokes bad_orient.spans)" = "$(strokes good_hr.spans)" ] && [ "$(strokes good_hr.spans | wc -l)" = 9 ]' "a face wound the wrong way is turned with its shell: drawn as the fixed cube: $(cat err.txt)"
# A Moebius strip cannot be oriented: one line says so, and the method needing no orientation
# draws it.
awk 'BEGIN { n = 12; pi = 3.14159265358979; for (i = 0; i < n; i++) {
  t = 2 * pi * i / n; p = pi * i / n; cx = 10 * cos(t); cy = 10 * sin(t);
  ox = 3 * cos(p) * cos(t); oy = 3 * cos(p) * sin(t); oz = 3 * sin(p);
  printf "v %f %f %f\nv %f %f %f\n", cx + ox, cy + oy, oz, cx - ox, cy - oy, -oz }
  for (i = 0; i < n - 1; i++) printf "f %d %d %d %d\n", 2*i+1, 2*i+2, 2*i+4, 2*i+3
  printf "f %d %d %d %d\n", 2*n-1, 2*n, 1, 2 }' > moebius.obj
# STL and PLY where OBJ goes, any case: the cube as an ASCII STL soup (welded by default) and a
# PLY named in capitals draw the cube's 9 visible edges; in a job too, with 'weld off' refused
# by nothing but drawing each shared edge twice.
awk '$1 == "v" { v[++n] = $2 " " $3 " " $4 } $1 == "f" { printf "facet normal 0 0 0\nouter loop\nvertex %s\nvertex %s\nvertex %s\nendloop\nendfacet\nfacet normal 0 0 0\nouter loop\nvertex %s\nvertex %s\nvertex %s\nendloop\nendfacet\n", v[$2], v[$3], v[$4], v[$2], v[$4], v[$5] }' good.obj | { echo "solid cube"; cat; echo "endsolid cube"; } > cube_soup.stl
{ printf 'ply\nformat ascii 1.0\nelement vertex 8\nproperty float x\nproperty float y\nproperty float z\nelement face 6\nproperty list uchar int vertex_indices\nend_header\n'
  awk '$1 == "v" { print $2, $3, $4 } $1 == "f" { print 4, $2 - 1, $3 - 1, $4 - 1, $5 - 1 }' good.obj; } > CUBE.PLY
for m in cube_soup.stl CUBE.PLY; do
  "$tool" plot $m --view 30,25 --mode hidden-removed -o m.svg --spans m.spans --stats 2> err.txt
  rc=$?
  expect '[ $rc -eq 0 ] && grep -q "^method=qi" err.txt && [ "$(strokes m.spans)" = "$(strokes good_hr.spans)" ]' "$m draws as cube.obj, by QI: $(cat err.txt)"
done
"$tool" plot cube_soup.stl --weld off --view 30,25 --mode all -o m.svg --spans m.spans
expect '[ "$(grep -c "^s " m.spans)" = 36 ]' "--weld off leaves the soup's 12 triangles with 36 edges"
printf 'scene cube_soup.stl\ndrawing hidden-removed\nview 30,25\nweld 0\n' > stl.job
"$tool" sim stl.job -o stl.trace 2> err.txt
expect '[ $? -eq 0 ] && [ -s stl.trace ]' "a job plots an STL scene: $(cat err.txt)"
printf 'scene cube_soup.stl\ndrawing hidden-removed\nweld -1\n' > badweld.job
"$tool" sim badweld.job -o bw.trace 2> err.txt
rc=$?
expect '[ $rc -ne 0 ] && grep -q -- "--weld .-1. must be" err.txt' "a bad weld is refused: $(cat err.txt)"
"$tool" plot moebius.obj --view 30,25 --mode hidden-removed -o moebius.svg --stats 2> err.txt
rc=$?
expect '[ $rc -eq 0 ] && [ "$(grep -c "^haloplot: " err.txt)" = 1 ] && grep -q "moebius.obj: its shell cannot be oriented: a twist (two faces wound the same way along their side) from (.*) to (.*), of the face on line [0-9]*; faces hide from both sides" err.txt && grep -q "^method=qi" err.txt && grep -q "^qi_two_sided=1" err.txt' "a Moebius strip is drawn by QI with both sides hiding, said in one line: $(cat err.txt)"
printf 'v 0 0 0\nv 4 0 0\nv 4 4 0\nv 0 4 1\nf 1 2 3 4\n' > sheet.obj
"$tool" plot sheet.obj --mode hidden-removed -o sheet.svg 2> err.txt
rc=$?
expect '[ $rc -eq 0 ] && grep -q "sheet.obj: its shell is open as made: no other open side.s corner lies within 1/8 of a side.s length, so no weld closes it; faces hide from both sides, so the hidden lines are right" err.txt' "an open surface is reported: $(cat err.txt)"
"$tool" plot good.obj --mode hidden-sketchy -o x.svg 2> err.txt
expect '[ $? -ne 0 ] && grep -q -- "--mode .hidden-sketchy. must be" err.txt && [ ! -e x.svg ]' "a bad --mode is named"
"$tool" plot obj.edges --mode hidden-removed -o x.svg 2> err.txt
rc=$?
expect '[ $rc -ne 0 ] && grep -q "need faces" err.txt' "hidden lines from an .edges file are refused: $(cat err.txt)"
"$tool" plot good.obj --mode hidden-dashed --dash 2,zero -o x.svg 2> err.txt
expect '[ $? -ne 0 ] && grep -q -- "--dash" err.txt' "a bad --dash is named"
"$tool" plot good.obj --halo 40 --outline -o x.svg 2> err.txt
expect '[ $? -ne 0 ] && grep -q -- "--outline needs the faces" err.txt' "--outline with haloed lines is refused"
"$tool" plot good.obj --halo 40 --no-intersections -o x.svg 2> err.txt
expect '[ $? -ne 0 ] && grep -q -- "--no-intersections needs the faces" err.txt' "--no-intersections with haloed lines is refused"
# Two boxes through each other: the lines where their faces cross are drawn unless switched off.
{ printf 'v 0 0 0\nv 2 0 0\nv 0 2 0\nv 2 2 0\nv 0 0 2\nv 2 0 2\nv 0 2 2\nv 2 2 2\n'
  printf 'v 1 0.5 0.5\nv 3 0.5 0.5\nv 1 2.5 0.5\nv 3 2.5 0.5\nv 1 0.5 2.5\nv 3 0.5 2.5\nv 1 2.5 2.5\nv 3 2.5 2.5\n'
  for b in 0 8; do
    printf 'f %d %d %d %d\n' $((b + 1)) $((b + 3)) $((b + 4)) $((b + 2)) $((b + 5)) $((b + 6)) $((b + 8)) $((b + 7)) \
      $((b + 1)) $((b + 2)) $((b + 6)) $((b + 5)) $((b + 3)) $((b + 7)) $((b + 8)) $((b + 4)) \
      $((b + 1)) $((b + 5)) $((b + 7)) $((b + 3)) $((b + 2)) $((b + 4)) $((b + 8)) $((b + 6))
  done; } > boxes.obj
"$tool" plot boxes.obj --view 30,25 --mode hidden-removed -o lines.svg --spans lines.spans --stats 2> lines.txt
"$tool" plot boxes.obj --view 30,25 --mode hidden-removed -o nolines.svg --spans nolines.spans --no-intersections 2> /dev/null
expect '[ "$(sed -n "s/^intersection_segments=//p" lines.txt)" -gt 0 ] && [ "$(grep -c "^s " lines.spans)" -gt "$(grep -c "^s " nolines.spans)" ]' "intersection lines are drawn by default, left out with --no-intersections: $(grep -E "^intersection_(segments|pieces)=" lines.txt | tr '\n' ' ')"
"$tool" plot good.obj --mode hidden-removed --halo 40 -o x.svg 2> err.txt
expect '[ $? -ne 0 ] && grep -q -- "--halo belongs to --mode haloed" err.txt' "--halo with a hidden-line mode is refused"

# The same modes reach the step trace, the G-code and the HPGL through a .job file.
printf 'scene good.obj\ndrawing hidden-dashed\nview 30,25\ndash 1 0.5\noutline on\n' > solid.job
"$tool" sim solid.job -o solid.trace --gcode solid.gcode --hpgl solid.hpgl --stats 2> err.txt
rc=$?
expect '[ $rc -eq 0 ] && [ -s solid.trace ] && grep -q "^G1" solid.gcode && grep -q "PD" solid.hpgl' "sim draws a hidden-dashed job: $(cat err.txt)"
"$tool" replay solid.trace -o solid_replay.svg --stats 2> replay.txt
expect '[ "$(grep "^strokes=" replay.txt | cut -d= -f2)" -gt 12 ]' "the replayed trace holds the dashes"
printf 'scene good.obj\ndrawing hidden-removed\ndash 1 nothing\n' > badjob.job
"$tool" sim badjob.job -o x.trace 2> err.txt
rc=$?
expect '[ $rc -ne 0 ] && grep -q "badjob.job:3:" err.txt && [ ! -e x.trace ]' "a bad job setting names its line: $(cat err.txt)"
printf 'scene obj.edges\ndrawing hidden-removed\n' > edgesjob.job
"$tool" sim edgesjob.job -o x.trace 2> err.txt
expect '[ $? -ne 0 ] && grep -q "needs a model scene" err.txt' "hidden lines of an .edges scene are refused in a job"


# Hatching (Franklin 1980's shading, for a pen): on the plot, in the spans, through a job.
"$tool" plot good.obj --view 30,25 --mode hidden-removed --hatch 1,30,90 -o hatch.svg --spans hatch.spans --stats 2> hatch.txt
rc=$?
expect '[ $rc -eq 0 ] && [ "$(grep -c "^h " hatch.spans)" -gt 10 ] && grep -q "^hatch_strokes=" hatch.txt' "--hatch hatches the visible faces: $(cat hatch.txt)"
"$tool" plot good.obj --mode hidden-removed --hatch 1,sideways -o x.svg 2> err.txt
rc=$?
expect '[ $rc -ne 0 ] && grep -q -- "--hatch" err.txt' "a bad --hatch is named"
printf 'scene good.obj\ndrawing hidden-removed\nview 30,25\nhatch 1 30 90\n' > hatch.job
"$tool" sim hatch.job -o hatch.trace --stats 2> hatchsim.txt
rc=$?
expect '[ $rc -eq 0 ] && [ "$(grep "^edges=" hatchsim.txt | cut -d= -f2)" -gt 20 ]' "a job hatches through the simulator: $(cat hatchsim.txt | head -3)"

# Bands (--arena, the job's arena): the controller's fixed arena on the host, the same picture.
"$tool" plot scene.edges --halo 60 -o band.svg --spans band.spans --arena 8192 --stats 2> band.txt
rc=$?
expect '[ $rc -eq 0 ] && cmp -s a.spans band.spans && cmp -s a.svg band.svg' "plot --arena draws what plot draws: $(head -3 band.txt)"
expect '[ "$(sed -n "s/^bands=//p" band.txt)" -gt 1 ]' "8 KB takes more than one band: $(grep '^bands=' band.txt)"
"$tool" plot scene.edges --halo 60 -o tiny.svg --arena 1024 2> err.txt
rc=$?
expect '[ $rc -ne 0 ] && grep -q "arena of 1024 bytes too small: a band one row high needs [0-9]*" err.txt && [ ! -e tiny.svg ]' "a too small arena names the bytes a band needs: $(cat err.txt)"
"$tool" plot scene.edges --halo 60 -o x.svg --arena 65536 --cut x.cut 2> err.txt
expect '[ $? -ne 0 ] && grep -q -- "--cut" err.txt' "--cut with --arena is refused by name"
printf 'scene scene.edges\ndrawing haloed\nhalo 60\narena 16384\n' > arena.job
"$tool" sim arena.job -o arena.trace --stats 2> arenasim.txt
rc=$?
expect '[ $rc -eq 0 ] && [ "$(sed -n "s/^bands=//p" arenasim.txt)" -gt 1 ] && [ "$(sed -n "s/^spans=//p" arenasim.txt)" = "$(grep -c "^s " a.spans)" ]' "a job with an arena plots in bands, every piece: $(grep -E "^(bands|spans)=" arenasim.txt | tr '\n' ' ')"
"$tool" replay arena.trace -o arena_replay.svg --stats 2> replay.txt
expect '[ $? -eq 0 ]' "the banded trace replays"
"$tool" sim arena.job -o arena.btrace --binary 2> err.txt
"$tool" replay arena.btrace -o arena_breplay.svg 2>> err.txt
rc=$?
expect '[ $rc -eq 0 ] && [ "$(wc -c < arena.btrace)" -lt "$(wc -c < arena.trace)" ] && cmp -s arena_replay.svg arena_breplay.svg' "the binary trace is smaller and replays to the same picture: $(cat err.txt)"
# A solid's hidden lines in bands: a job with an arena works them out band by band, as the
# controller does, outlines and hatching included.
"$tool" demo-scene --cubes 4 -o cubes4.obj
printf 'scene cubes4.obj\ndrawing hidden-dashed\nview 30,25\ndash 2 1\narena 32768\n' > solid_arena.job
"$tool" sim solid_arena.job -o solid_arena.trace --stats 2> solid_arena.txt
rc=$?
expect '[ $rc -eq 0 ] && [ "$(sed -n "s/^bands=//p" solid_arena.txt)" -gt 1 ] && [ -s solid_arena.trace ]' "a hidden-line job with an arena plots in bands: $(grep -E "^(bands|band_peak_bytes)=" solid_arena.txt | tr '\n' ' ')"
{ cat solid_arena.job; echo "outline on"; } > solid_outline.job
"$tool" sim solid_outline.job -o solid_outline.trace --stats 2> solid_outline.txt
rc=$?
expect '[ $rc -eq 0 ] && [ "$(sed -n "s/^pen_down_length=//p" solid_outline.txt)" -gt "$(sed -n "s/^pen_down_length=//p" solid_arena.txt)" ]' "outlines in bands add ink: $(grep pen_down_length solid_outline.txt) against $(grep pen_down_length solid_arena.txt)"
# Hatching in bands: more ink than the lines alone, and as much as the whole model's hatching
# (the strokes are the same, cut at the borders: solid_bands checks them one by one).
{ cat solid_arena.job; echo "hatch 3 30 90"; } > solid_hatch.job
grep -v '^arena' solid_hatch.job > solid_hatch_whole.job
"$tool" sim solid_hatch.job -o solid_hatch.trace --stats 2> solid_hatch.txt
rc=$?
"$tool" sim solid_hatch_whole.job -o solid_hatch_whole.trace --stats 2> solid_hatch_whole.txt
down() { sed -n 's/^pen_down_length=//p' "$1"; }
expect '[ $rc -eq 0 ] && [ "$(sed -n "s/^bands=//p" solid_hatch.txt)" -gt 1 ] && [ "$(down solid_hatch.txt)" -gt $(( $(down solid_arena.txt) * 2 )) ] && [ $(( 1000 * $(down solid_hatch.txt) / $(down solid_hatch_whole.txt) )) -ge 995 ] && [ $(( 1000 * $(down solid_hatch.txt) / $(down solid_hatch_whole.txt) )) -le 1005 ]' "a hatched job with an arena plots in bands, as much ink as without: $(grep -E "^(bands|pen_down_length)=" solid_hatch.txt solid_hatch_whole.txt solid_arena.txt | tr '\n' ' ')"
"$tool" plot cubes4.obj --mode hidden-dashed --hatch 3 --arena 32768 -o solid_arena.svg 2> err.txt
rc=$?
expect '[ $rc -ne 0 ] && grep -q "arena BYTES" err.txt && [ ! -e solid_arena.svg ]' "plot --arena of a solid is refused by name, not ignored: $(cat err.txt)"
# Intersection lines in bands too: the boxes through each other, with and without them (2,304
# bytes: the whole model needs more since its CUT pairs only the marked edges, so it bands).
printf 'scene boxes.obj\ndrawing hidden-removed\nview 30,25\narena 2304\n' > lines_arena.job
{ cat lines_arena.job; echo "intersections off"; } > nolines_arena.job
"$tool" sim lines_arena.job -o lines_arena.trace --stats 2> lines_arena.txt
rc=$?
"$tool" sim nolines_arena.job -o nolines_arena.trace --stats 2> nolines_arena.txt
expect '[ $rc -eq 0 ] && [ $? -eq 0 ] && [ "$(sed -n "s/^bands=//p" lines_arena.txt)" -gt 1 ] && [ "$(sed -n "s/^pen_down_length=//p" lines_arena.txt)" -gt "$(sed -n "s/^pen_down_length=//p" nolines_arena.txt)" ]' "intersection lines are drawn in bands, left out with 'intersections off': $(grep -E "^(bands|pen_down_length)=" lines_arena.txt nolines_arena.txt | tr '\n' ' ')"
# 4 KB: a band one row high of the 4 x 4 cubes needs 5,424 bytes (banded in the page turned a
# quarter, its rows are columns of the page; in the page's rows it needed 10,456).
sed 's/^arena .*/arena 4096/' solid_arena.job > solid_tiny.job
"$tool" sim solid_tiny.job -o solid_tiny.trace 2> err.txt
rc=$?
expect '[ $rc -ne 0 ] && grep -q "arena of 4096 bytes too small: a band one row high needs [1-9][0-9]*" err.txt && [ ! -e solid_tiny.trace ]' "a solid band that does not fit names the bytes it needs: $(cat err.txt)"
head -c 200 arena.btrace > cut.btrace
"$tool" replay cut.btrace -o cut.svg 2> err.txt
rc=$?
expect '[ $rc -ne 0 ] && grep -q "cut.btrace" err.txt && [ ! -e cut.svg ]' "a binary trace cut short is refused by name: $(cat err.txt)"

# Feed holds and resume in the simulator: bad counts are refused by name, good ones run.
printf 'scene scene.edges\ndrawing all\n' > hold.job
"$tool" sim hold.job -o bad.trace --pause-at 500,200 2> err.txt
rc=$?
expect '[ $rc -ne 0 ] && grep -q -- "--pause-at needs ascending" err.txt && [ ! -e bad.trace ]' "descending --pause-at is refused: $(cat err.txt)"
"$tool" sim hold.job -o bad.trace --resume-at x 2> err.txt
rc=$?
expect '[ $rc -ne 0 ] && grep -q -- "--resume-at needs" err.txt && [ ! -e bad.trace ]' "a --resume-at that is no count is refused: $(cat err.txt)"
"$tool" sim hold.job -o held.trace --pause-at 200,900 --stats 2> held.txt && "$tool" sim hold.job -o resumed.trace --resume-at 900 2>> held.txt
rc=$?
expect '[ $rc -eq 0 ] && grep -q "^holds=2$" held.txt && [ -s resumed.trace ]' "sim --pause-at makes the holds and --resume-at runs: $(cat held.txt | grep -E "holds|haloplot")"

# finish: home (the default) ends the trace at the origin, stay where the last stroke ended.
printf 'scene scene.edges\ndrawing all\n' > home.job
printf 'scene scene.edges\ndrawing all\nfinish stay\n' > stay.job
"$tool" sim home.job -o home.trace --gcode home.gcode 2> err.txt && "$tool" sim stay.job -o stay.trace 2>> err.txt
rc=$?
expect '[ $rc -eq 0 ] && [ "$(tail -1 home.trace)" != "$(tail -1 stay.trace)" ] && grep -q "X0.000 Y0.000" home.gcode' "finish home travels to the origin, stay does not: $(cat err.txt; tail -n 1 home.trace stay.trace; grep -c . home.gcode)"

# Outputs: "-" is standard output; links are written through, devices and FIFOs too, never
# replaced; a directory is refused by name; a failed secondary output leaves no output at all.
"$tool" plot scene.edges --halo 5 -o - > stdout.svg 2> err.txt
rc=$?
expect '[ $rc -eq 0 ] && [ ! -e - ] && grep -q "<svg" stdout.svg' "-o - writes the SVG to standard output: $(cat err.txt)"
: > real.svg
ln -s real.svg link.svg
"$tool" plot scene.edges --halo 5 -o link.svg 2> err.txt
rc=$?
expect '[ $rc -eq 0 ] && [ -L link.svg ] && grep -q "<svg" real.svg' "an output that is a symlink is written through, the link kept: $(cat err.txt)"
mkfifo pipe.svg
timeout 30 cat pipe.svg > from_pipe.svg &
reader=$!
"$tool" plot scene.edges --halo 5 -o pipe.svg 2> err.txt
rc=$?
wait $reader
expect '[ $rc -eq 0 ] && [ -p pipe.svg ] && cmp -s from_pipe.svg stdout.svg' "a FIFO is written through and stays a FIFO: $(cat err.txt)"
# A device node of our own (a copy of /dev/null, so a tool that replaced it harms nothing).
if mknod null.dev c 1 3 2> /dev/null; then
  "$tool" plot scene.edges --halo 5 -o null.dev 2> err.txt
  rc=$?
  expect '[ $rc -eq 0 ] && [ -c null.dev ]' "a character device stays a device: $(cat err.txt)"
fi
mkdir adir
"$tool" plot scene.edges --halo 5 -o adir 2> err.txt
rc=$?
expect '[ $rc -ne 0 ] && grep -q "adir: cannot write there (is a directory)" err.txt && [ -d adir ]' "a directory is refused by name: $(cat err.txt)"
"$tool" plot scene.edges --halo 5 -o first.svg --spans no_such_dir/x.spans 2> err.txt
rc=$?
expect '[ $rc -ne 0 ] && [ ! -e first.svg ] && [ ! -e first.svg.tmp ]' "a failed secondary output leaves no SVG: $(cat err.txt; ls)"
"$tool" sim home.job -o second.trace --gcode no_such_dir/x.gcode 2> err.txt
rc=$?
expect '[ $rc -ne 0 ] && [ ! -e second.trace ]' "a failed G-code leaves no trace: $(cat err.txt)"

# Hostile lines and fields: bounded memory and time, a short excerpt in the message.
python3 -c "open('longline.edges','w').write('1 2 3 4 5 ' + '9' * 50000000 + '\\n')"
/usr/bin/time -f "%M" -o mem.txt "$tool" plot longline.edges --halo 5 -o x.svg 2> err.txt
rc=$?
expect '[ $rc -ne 0 ] && grep -q "longline.edges:1: line longer than 1048576 bytes" err.txt && [ "$(tail -1 mem.txt)" -lt 200000 ]' "a 50 MB line is refused in bounded memory: $(cat err.txt mem.txt | cut -c1-200)"
python3 -c "open('longfield.edges','w').write('1 2 3 4 5 ' + '7' * 5000 + '\\n')"
"$tool" plot longfield.edges --halo 5 -o x.svg 2> err.txt
rc=$?
expect '[ $rc -ne 0 ] && [ "$(wc -c < err.txt)" -lt 300 ] && grep -q "77777\\.\\.\\." err.txt' "a long field is quoted as a short excerpt: $(cut -c1-200 err.txt)"
python3 -c "open('utf16.obj','wb').write('v 0 0 0\\nv 1 0 0\\nv 0 1 0\\nf 1 2 3\\n'.encode('utf-16'))"
"$tool" plot utf16.obj --mode all -o x.svg 2> err.txt
rc=$?
expect '[ $rc -ne 0 ] && grep -q "utf16.obj:1: UTF-16 text" err.txt' "UTF-16 is refused by name: $(cat err.txt)"
printf '\xef\xbb\xbfv 0 0 0\nv 1 0 0 0.5 0.5 0.5\nv 0 1 0\nf 1 2 3\n' > bom.obj
"$tool" plot bom.obj --mode hidden-removed -o x.svg 2> err.txt
rc=$?
expect '[ $rc -eq 0 ]' "a UTF-8 byte-order mark and vertex colours are read: $(cat err.txt)"
printf 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4 1 2 3 4\n' > twice.obj
"$tool" plot twice.obj --mode hidden-removed -o x.svg 2> err.txt
rc=$?
expect '[ $rc -eq 0 ]' "a face that repeats its loop is drawn: $(cat err.txt)"

# Settings named with their line and the reason.
for bad in 'kinematics delta|kinematics takes cartesian | corexy, not .delta.' \
           'steps 1000/1|steps 1000/1: the motor steps per plot step must lie in' \
           'kinematcs corexy|unknown setting .kinematcs. (did you mean .kinematics.?)' \
           'arena 12|arena needs the controller.s job arena' \
           'finish sideways|finish is home' \
           'travel-speed 30000|a speed of 30000 steps/s at steps 1/1 needs 30000 motor steps/s'; do
  printf 'scene scene.edges\n%s\n' "${bad%%|*}" > setting.job
  "$tool" sim setting.job -o x.trace 2> err.txt
  rc=$?
  expect '[ $rc -ne 0 ] && grep -q "setting.job:2: ${bad#*|}" err.txt' "'${bad%%|*}' is named with its line: $(cat err.txt)"
done

# Help, version, missing and misspelt arguments, flags that do not go together.
for cmd in plot sim cut draw replay send view2d demo-scene random-scene; do
  "$tool" "$cmd" --help > help.txt 2> err.txt
  expect '[ $? -eq 0 ] && grep -q "haloplot $cmd " help.txt' "$cmd --help prints its usage"
done
"$tool" --version > v.txt
rc=$?
expect '[ $rc -eq 0 ] && grep -qE "^haloplot [0-9]+\\.[0-9]+\\.[0-9]+$" v.txt' "--version: $(cat v.txt)"
"$tool" plot scene.edges --halo 5 2> err.txt
rc=$?
expect '[ $rc -ne 0 ] && grep -q "plot: missing -o OUTPUT" err.txt' "a missing -o is named: $(head -1 err.txt)"
"$tool" plot scene.edges --hallo 5 -o x.svg 2> err.txt
rc=$?
expect '[ $rc -ne 0 ] && grep -q "unknown option --hallo (did you mean --halo?)" err.txt' "a misspelt flag gets a suggestion: $(cat err.txt)"
"$tool" plot scene.edges --halo 5 --hatch 1 -o x.svg 2> err.txt
rc=$?
expect '[ $rc -ne 0 ] && grep -q -- "--hatch is for solid drawings" err.txt' "--hatch with --halo is refused: $(cat err.txt)"
start=$(date +%s)
"$tool" send home.job --port /dev/ttyHALOPLOTNONE 2> err.txt
rc=$?
expect '[ $rc -ne 0 ] && [ $(( $(date +%s) - start )) -lt 5 ] && grep -q "no such serial device" err.txt' "send to a missing device fails at once: $(cat err.txt)"

# The SVG is the page (A4 landscape by default, in mm); an .edges scene's steps land at the
# plotter's steps per mm: at 40 the drawing is twice as wide as at 80.
"$tool" plot scene.edges --halo 5 -o mm80.svg && "$tool" plot scene.edges --halo 5 --steps-per-mm 40 -o mm40.svg
w80=$(python3 "$here/svg_page_check.py" extent mm80.svg)
w40=$(python3 "$here/svg_page_check.py" extent mm40.svg)
expect 'grep -q "width=\"297mm\" height=\"210mm\" viewBox=\"0 0 297 210\"" mm80.svg && python3 -c "import sys; w80, w40 = map(float, sys.argv[1:]); sys.exit(not (w80 > 1 and abs(w40 - 2 * w80) < 0.002))" "$w80" "$w40"' "SVG page A4 landscape, drawing width in mm: $w80 at 80 steps/mm, $w40 at 40"

# Nothing to draw is an error, not an empty picture.
: > empty.edges
"$tool" plot empty.edges --halo 5 -o nothing.svg 2> err.txt
rc=$?
expect '[ $rc -ne 0 ] && grep -q "empty.edges: no edges: nothing to draw" err.txt && [ ! -e nothing.svg ]' "an empty scene is refused: $(cat err.txt)"
printf 'v 1 1 1\nv 1 1 1\nv 1 1 1\nf 1 2 3\n' > point.obj
"$tool" plot point.obj --halo 5 -o x.svg 2> err.txt
rc=$?
expect '[ $rc -ne 0 ] && grep -q "point.obj" err.txt' "a model with all vertices equal is refused: $(cat err.txt)"

# Up axis: a Y-up file (the default, as Blender and most exporters write) and the same model
# written Z-up with --up z give the same projected edges; a bad value is named.
printf 'v 0 0 0\nv 4 0 0\nv 4 1 0\nv 0 1 0\nv 0 0 9\nv 4 0 9\nl 1 2 3 4 1 5 6\n' > zup.obj
awk '$1 == "v" { printf "v %s %s %s\n", $2, $4, -$3; next } { print }' zup.obj > yup.obj
"$tool" plot zup.obj --up z --halo 5 -o z.svg --dump-edges z.edges && "$tool" plot yup.obj --halo 5 -o y.svg --dump-edges y.edges
rc=$?
grep -v '^#' z.edges > z.data; grep -v '^#' y.edges > y.data; grep -v '^#' yz.edges > yz.data 2> /dev/null
expect '[ $rc -eq 0 ] && [ -s z.data ] && cmp -s z.data y.data' "a Y-up file and its Z-up twin project alike"
"$tool" plot zup.obj --halo 5 -o yz.svg --dump-edges yz.edges
grep -v '^#' yz.edges > yz.data
expect '! cmp -s z.data yz.data' "the up axis matters (a Z-up file read as Y-up lies on its back)"
"$tool" plot zup.obj --up w --halo 5 -o x.svg 2> err.txt
rc=$?
expect '[ $rc -ne 0 ] && grep -q -- "--up .w. must be x, y, z, -x, -y or -z" err.txt' "a bad --up is named: $(cat err.txt)"

# A legal but absurd acceleration is warned about; a sane one is not.
printf 'scene scene.edges\ndrawing all\naccel 1\n' > slow.job
"$tool" sim slow.job -o slow.trace 2> err.txt
rc=$?
expect '[ $rc -eq 0 ] && grep -q "warning: the plot takes .* is accel 1 steps/s^2 meant" err.txt' "accel 1 is warned about: $(cat err.txt)"
"$tool" sim home.job -o home2.trace 2> err.txt
expect '! grep -q warning err.txt' "a sane job has no warning: $(cat err.txt)"

echo "cli: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
