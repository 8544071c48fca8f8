#!/usr/bin/env bash
# plot --gcode/--hpgl: the plotter's files of the drawing, from the path the job plans, with no
# step simulated. Checked against `sim` writing the same job (the same bytes, for a haloed
# edges scene, a hidden-removed mesh, a hidden-dashed solid with outlines and hatching, mode
# all, and a Z-axis pen with feeds given in mm/min), the plot-time estimate against the step
# simulation's end time, and each pen profile against a hand-written G-code of one stroke.
set -u
tool="$1"
src="$2"  # the source tree (scenes/)
# shellcheck source=../support/checks.sh
. "$(cd "$(dirname "$0")" && pwd)/../support/checks.sh"

cd "$work"
"$tool" demo-scene --cubes 4 -o scene.edges
"$tool" demo-scene --cubes 2 -o cubes.obj
cp "$src/scenes/linked_tori.obj" tori.obj

# same NAME "PLOT OPTIONS" "JOB LINES": plot and sim of the same drawing write the same G-code
# and HPGL, and the estimate is within 0.5 % of the step simulation's plot time.
same() {
  local name="$1" plot_opts="$2" job="$3" scene="$4"
  printf "scene %s\n$job" "$scene" > "$name.job"
  # shellcheck disable=SC2086
  "$tool" plot "$scene" $plot_opts -o "$name.svg" --gcode "$name.p.gcode" --hpgl "$name.p.hpgl" \
    --stats 2> "$name.plot.txt"
  local rc=$?
  "$tool" sim "$name.job" -o "$name.trace" --gcode "$name.s.gcode" --hpgl "$name.s.hpgl" \
    --stats 2> "$name.sim.txt"
  expect '[ $rc -eq 0 ] && [ -s $name.p.gcode ] && [ -s $name.p.hpgl ]' \
    "$name: plot writes G-code and HPGL: $(tail -3 "$name.plot.txt")"
  expect 'cmp -s $name.p.gcode $name.s.gcode' "$name: plot --gcode equals sim --gcode"
  expect 'cmp -s $name.p.hpgl $name.s.hpgl' "$name: plot --hpgl equals sim --hpgl"
  expect 'grep -q "^haloplot: plot time about \([0-9]* h \)\?[0-9]* min [0-9]* s" $name.plot.txt' \
    "$name: the estimate is on stderr: $(cat "$name.plot.txt")"
  local est sim_s
  est=$(sed -n 's/^estimate_s=//p' "$name.plot.txt")
  sim_s=$(sed -n 's/^plot_s=//p' "$name.sim.txt")
  expect 'awk -v e="$est" -v s="$sim_s" "BEGIN { d = e - s; if (d < 0) d = -d; exit !(s > 0 && d <= 0.005 * s) }"' \
    "$name: estimate $est s within 0.5 % of the simulated $sim_s s"
}
same halo "--halo 40" "halo 40\n" scene.edges
same exact "--halo 30 --exact-halo" "halo 30\nhalo-mode exact\n" scene.edges
same removed "--mode hidden-removed --view 20,30" "drawing hidden-removed\nview 20,30\n" tori.obj
same dashed "--mode hidden-dashed --dash 1,0.5 --outline --hatch 3,30" \
  "drawing hidden-dashed\ndash 1 0.5\noutline on\nhatch 3 30\n" cubes.obj
same all "--mode all" "drawing all\n" cubes.obj
same zpen "--halo 40 --pen z --z-up 4 --z-down -0.5 --z-feed 800 --draw-feed 3000 --travel-feed 7000" \
  "halo 40\npen z\nz-up 4\nz-down -0.5\nz-feed 800\ndraw-feed 3000\ntravel-feed 7000\n" scene.edges
expect '! cmp -s halo.p.gcode zpen.p.gcode' "the pen profile and feeds change the G-code"
# Slower feeds plan a slower plot: the estimate follows the machine the feeds set.
est_fast=$(sed -n 's/^estimate_s=//p' halo.plot.txt)
est_slow=$(sed -n 's/^estimate_s=//p' zpen.plot.txt)
expect 'awk -v a="$est_fast" -v b="$est_slow" "BEGIN { exit !(b > a) }"' \
  "feeds below the default speeds take longer ($est_slow s against $est_fast s)"

# Each pen profile against a hand-written G-code of one stroke: the edge (80,160)-(880,160) in
# steps is (1,2)-(11,2) mm at 80 steps/mm; the default machine draws at 6000 steps/s (4500
# mm/min), travels at 12000 (9000 mm/min), and its pen takes 0.15 + 0.05 s; the plot ends home.
printf '80 160 0 880 160 0\n' > one.edges
profile() {
  local name="$1"
  shift
  "$tool" plot one.edges --halo 0 -o "$name.svg" --gcode "$name.gcode" "$@" 2> "$name.err"
  expect 'cmp -s $name.gcode $name.want' "pen profile $name: got
$(cat "$name.gcode" "$name.err")
wanted
$(cat "$name.want")"
}
printf '%s\n' '; haloplot G-code' G21 G90 M5 'G4 P0.200' 'G0 X1.000 Y2.000 F9000.000' \
  'M3 S1000' 'G4 P0.200' 'G1 X11.000 Y2.000 F4500.000' M5 'G4 P0.200' \
  'G0 X0.000 Y0.000 F9000.000' M2 > servo.want
profile servo
printf '%s\n' '; haloplot G-code' G21 G90 M5 'G4 P0.350' 'G0 X1.000 Y2.000 F6000.000' \
  'M3 S255' 'G4 P0.350' 'G1 X11.000 Y2.000 F1200.500' M5 'G4 P0.350' \
  'G0 X0.000 Y0.000 F6000.000' M2 > servo2.want
profile servo2 --pen servo --servo-down 255 --pen-dwell 0.35 --draw-feed 1200.5 --travel-feed 6000
printf '%s\n' '; haloplot G-code' G21 G90 'G0 Z3.000' 'G0 X1.000 Y2.000 F9000.000' \
  'G1 Z-1.250 F300.000' 'G1 X11.000 Y2.000 F4500.000' 'G0 Z3.000' \
  'G0 X0.000 Y0.000 F9000.000' M2 > z.want
profile z --pen z --z-up 3 --z-down -1.25 --z-feed 300
printf '%s\n' '; haloplot G-code' G21 G90 'M280 P0 S90' 'G4 P0.15' 'G0 X1.000 Y2.000 F9000.000' \
  'M280 P0 S30' 'G1 X11.000 Y2.000 F4500.000' 'M280 P0 S90' 'G4 P0.15' \
  'G0 X0.000 Y0.000 F9000.000' M2 > custom.want
profile custom --pen custom --pen-up-gcode 'M280 P0 S90\nG4 P0.15' --pen-down-gcode 'M280 P0 S30'
# The same profile from a job's keys (a custom command's words as the line gives them).
printf 'scene one.edges\nhalo 0\npen custom\npen-up-gcode M280 P0 S90\\nG4 P0.15\npen-down-gcode M280 P0 S30\n' > custom.job
"$tool" sim custom.job -o custom.trace --gcode custom_job.gcode
expect 'cmp -s custom_job.gcode custom.want' "job keys give the custom profile: $(cat custom_job.gcode)"

# Refusals, by name.
"$tool" plot one.edges --halo 0 -o x.svg --pen z 2> err.txt
rc=$?
expect '[ $rc -ne 0 ] && grep -q -- "--pen .*--gcode" err.txt && [ ! -e x.svg ]' "a pen option without --gcode: $(cat err.txt)"
"$tool" plot one.edges --halo 0 -o x.svg --gcode x.gcode --pen z --servo-down 5 2> err.txt
rc=$?
expect '[ $rc -ne 0 ] && grep -q -- "--servo-down is for --pen servo" err.txt' "a servo option with the Z pen: $(cat err.txt)"
"$tool" plot one.edges --halo 0 -o x.svg --gcode x.gcode --pen custom 2> err.txt
rc=$?
expect '[ $rc -ne 0 ] && grep -q -- "--pen-up-gcode" err.txt' "custom pen without commands: $(cat err.txt)"
"$tool" plot one.edges --halo 0 -o x.svg --gcode x.gcode --draw-feed 0 2> err.txt
rc=$?
expect '[ $rc -ne 0 ] && grep -q -- "--draw-feed" err.txt' "a zero feed: $(cat err.txt)"
printf 'scene one.edges\nhalo 0\npen z\nservo-down 7\n' > bad.job
"$tool" sim bad.job -o bad.trace --gcode bad.gcode 2> err.txt
rc=$?
expect '[ $rc -ne 0 ] && grep -q "bad.job:4: servo-down is for pen servo" err.txt' "a job's pen key names its line: $(cat err.txt)"
printf 'scene one.edges\nhalo 0\ndraw-speed 3000\ndraw-feed 2000\n' > both.job
"$tool" sim both.job -o both.trace 2> err.txt
rc=$?
expect '[ $rc -ne 0 ] && grep -q "draw-feed and draw-speed" err.txt' "a feed and a speed together: $(cat err.txt)"
"$tool" plot scene.edges --halo 40 --arena 65536 -o x.svg --gcode x.gcode 2> err.txt
rc=$?
expect '[ $rc -ne 0 ] && grep -q -- "--arena" err.txt' "--gcode with --arena: $(cat err.txt)"

echo "plot_gcode: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
