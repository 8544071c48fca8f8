#!/usr/bin/env bash
# CTest camera: the model's orientation and the camera. (1) The linked tori rewritten with
# their axes permuted and negated (by awk, here) and read with the matching --up draw what
# the original draws with the default --up y, for all six axes (the turns docs/cli.md
# states); (2) --eye/--look-at along the direction of --view AZ,EL (the direction worked out
# here from the view convention) draws what --view draws, and with --fov what --perspective D
# draws for D = ceil(R / sin(fov / 2)) (R worked out by tests/cli/edges_compare.py from the
# file); (3) --roll DEG draws the unrolled picture turned DEG about its centre and fitted
# again (turned and refitted by edges_compare.py); (4) the refusals, and the job keys.
# Usage: camera.sh HALOPLOT SCENES_DIR
set -u
tool="$1"
tori="$2/linked_tori.obj"
cmp_edges="python3 $(cd "$(dirname "$0")" && pwd)/edges_compare.py"
# shellcheck source=../support/expect.sh
. "$(cd "$(dirname "$0")" && pwd)/../support/expect.sh"
# plot NAME ARGS...: a plot (hidden-removed for (1), else all: the projected scene is what is
# compared, and all is faster) and its projected scene (NAME.svg, NAME.edges).
mode=hidden-removed
plot() { local name=$1; shift; "$tool" plot "$@" --mode $mode -o "$name.svg" --dump-edges "$name.edges"; }
step=32  # one step in the dump's units (sub-step 5, the default)

plot ref "$tori"
cp ref.edges ref_hidden.edges
# (1) The default reads the file Y-up: world (x, -z, y). For each --up A, the file whose
# A-up turn gives that same world: world = turn_A(file'), so file' = turn_A^-1(x, -z, y).
#   z: (x,y,z)    -z: (x,-y,-z)   x: (-z,y,x)   -x: (z,y,-x)   -y: (x,z,-y)
declare -A rewrite=([y]='$2,$3,$4' [z]='$2,-$4,$3' [-z]='$2,$4,-$3' [-y]='$2,-$3,-$4'
  [x]='$3,-$4,-$2' [-x]='-$3,-$4,$2')
for up in y z -z -y x -x; do
  awk "\$1==\"v\"{print \"v\", ${rewrite[$up]}; next} {print}" "$tori" > "up$up.obj"
  plot "up$up" "up$up.obj" --up "$up"
  expect "$cmp_edges same ref_hidden.edges up$up.edges $step" "--up $up draws the Y-up original"
  expect "cmp ref.svg up$up.svg" "--up $up: the same SVG (the same integer world)"
done
# The check can fail: the -x file read as x (a half turn away) draws something else.
plot wrong "up-x.obj" --up x
expect "\$cmp_edges same ref.edges wrong.edges $step; [ \$? -eq 1 ]" "the -x file read with --up x differs"

mode=all

# (2) The view's direction toward the viewer, w = (-sin az cos el, -cos az cos el, sin el),
# in the Z-up world; a Y-up file holds the world's (x, y, z) as (x, z, -y).
eye_for() {  # AZ EL AT(x,y,z) UP -> an eye 7 units from AT along w, in file coordinates
  awk -v az="$1" -v el="$2" -v at="$3" -v up="$4" 'BEGIN {
    pi = atan2(0, -1); a = az * pi / 180; e = el * pi / 180; split(at, p, ",")
    wx = -sin(a) * cos(e); wy = -cos(a) * cos(e); wz = sin(e)
    if (up == "y") { fx = wx; fy = wz; fz = -wy } else { fx = wx; fy = wy; fz = wz }
    printf "%.9f,%.9f,%.9f\n", p[1] + 7 * fx, p[2] + 7 * fy, p[3] + 7 * fz }'
}
plot ref "$tori"
plot view "$tori" --view 30,40
plot cam "$tori" --eye "$(eye_for 30 40 0.3,-1,0.2 y)" --look-at 0.3,-1,0.2
expect "$cmp_edges same view.edges cam.edges $step" "--eye/--look-at along --view 30,40"
expect "$cmp_edges same ref.edges cam.edges $step" "and the default view is 30,40"
plot view2 "$tori" --view -120.5,-15 --up z
plot cam2 "$tori" --eye "$(eye_for -120.5 -15 1,2,3 z)" --look-at 1,2,3 --up z
expect "$cmp_edges same view2.edges cam2.edges $step" "--up z, --view -120.5,-15 as a camera"
expect "\$cmp_edges same view2.edges view.edges $step; [ \$? -eq 1 ]" "(a different view draws differently)"
read -r d centre <<< "$($cmp_edges depth_d "$tori" y 40)"
plot persp "$tori" --view 30,40 --perspective "$d"
plot fov "$tori" --eye "$(eye_for 30 40 "$centre" y)" --look-at "$centre" --fov 40
expect "$cmp_edges same persp.edges fov.edges $step" "--fov 40 is --perspective $d"
plot persp2 "$tori" --view 30,40 --perspective "$((d / 2))"
expect "\$cmp_edges same persp2.edges fov.edges $step; [ \$? -eq 1 ]" "(another distance draws differently)"
expect "\$cmp_edges same view.edges fov.edges $step; [ \$? -eq 1 ]" "(and orthographic differently)"

# (3) Roll: the unrolled picture turned about its centre and fitted again.
for roll in 90 -90 30 180; do
  plot "roll$roll" "$tori" --roll "$roll"
  expect "$cmp_edges roll ref.edges roll$roll.edges $roll 1" "--roll $roll"
done
expect "\$cmp_edges roll ref.edges roll90.edges -90 1; [ \$? -eq 1 ]" "(--roll 90 is not -90)"
plot rollp "$tori" --view 30,40 --perspective "$d" --roll 90
expect "$cmp_edges roll persp.edges rollp.edges 90 1" "--roll 90 in perspective"

# (4) Refusals, by name.
refuse() {  # MESSAGE ARGS...: the plot fails, nothing written, stderr has MESSAGE
  local msg=$1; shift
  rm -f r.svg
  expect "! \"$tool\" plot \"$tori\" --mode all -o r.svg $* 2> err.txt && grep -q -- \"$msg\" err.txt && [ ! -e r.svg ]" "refused: $*"
}
refuse "--view and --eye/--look-at both set the view" --eye 1,2,3 --look-at 0,0,0 --view 30,40
refuse "--perspective and --eye/--look-at both" --eye 1,2,3 --look-at 0,0,0 --perspective 900000
refuse "--fov is for a camera" --fov 30
refuse "--eye needs --look-at" --eye 1,2,3
refuse "--look-at needs --eye" --look-at 1,2,3
refuse "the same point" --eye 1,2,3 --look-at 1,2,3
refuse "--eye and --look-at must each be X,Y,Z" --eye 1,2 --look-at 0,0,0
refuse "--fov '180' must be" --eye 1,2,3 --look-at 0,0,0 --fov 180
refuse "--roll 'x' must be" --roll x
refuse "--up 'w' must be x, y, z, -x, -y or -z" --up w
"$tool" demo-scene -o flat.edges 2> /dev/null || printf '0 0 0 100 100 0\n' > flat.edges
expect "! \"$tool\" plot flat.edges --halo 5 -o r.svg --roll 30 2> err.txt && grep -q -- '--roll is for models' err.txt" "--roll on an .edges scene"

# Job keys: eye before look-at is fine; eye with view is refused at its line.
cp "$tori" tori.obj
printf 'scene tori.obj\ndrawing hidden-removed\nroll 90\neye %s\nlook-at 0.3,-1,0.2\n' \
  "$(eye_for 30 40 0.3,-1,0.2 y)" > cam.job
printf 'scene tori.obj\ndrawing hidden-removed\nview 30,40\nroll 90\n' > view.job
expect "\"$tool\" sim cam.job -o cam.trace --gcode cam.gcode && \"$tool\" sim view.job -o view.trace --gcode view.gcode && cmp cam.gcode view.gcode" "a job with eye, look-at and roll draws the view 30,40 job's G-code"
printf 'scene tori.obj\ndrawing hidden-removed\nview 30,40\n' > noroll.job
expect "\"$tool\" sim noroll.job -o noroll.trace --gcode noroll.gcode && ! cmp -s noroll.gcode view.gcode" "(and the job's roll is not ignored)"
printf 'scene tori.obj\ndrawing hidden-removed\neye 1,2,3\nlook-at 0,0,0\nview 30,40\n' > both.job
expect "! \"$tool\" sim both.job -o both.trace 2> err.txt && grep -q 'both.job:5: --view and --eye' err.txt" "job: eye with view refused at the view line"
printf 'scene tori.obj\nfov 30\n' > fov.job
expect "! \"$tool\" sim fov.job -o fov.trace 2> err.txt && grep -q 'fov.job:2: --fov is for a camera' err.txt" "job: fov without eye refused"

echo "camera: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
