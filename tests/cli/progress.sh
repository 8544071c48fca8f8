#!/usr/bin/env bash
# Progress on a terminal (cli/stage_progress.h): under a pseudo-terminal (util-linux `script`),
# with HALOPLOT_PROGRESS_AFTER_MS=0 so every stage counts as long whatever the machine's speed,
# each stage is announced at most once and the hidden lines are announced; CUT's counter shows
# once for a haloed plot with --gcode (it showed twice: the G-code's job ran its own CUT with
# the counter). With stderr a file nothing of it is printed, and with a wait longer than the
# plot nothing either. Usage: progress.sh HALOPLOT MODEL
set -u
tool="$1" model="$2"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
pass=0 fail=0
expect() { if eval "$1"; then pass=$((pass + 1)); else fail=$((fail + 1)); echo "FAILED: $2"; fi; }
command -v script > /dev/null || { echo "no util-linux script: skipped"; exit 77; }
on_terminal() {  # OUT AFTER_MS ARGS...: the tool's terminal output (stdout and stderr) in OUT
  local out="$1" after="$2"
  shift 2
  HALOPLOT_PROGRESS_AFTER_MS="$after" script -qec "$(printf '%q ' "$tool" "$@")" /dev/null |
    tr '\r' '\n' > "$out"
}
on_terminal removed.txt 0 plot "$model" --mode hidden-removed --hatch 1 -o r.svg --gcode r.gcode
expect 'grep -qx "haloplot: hidden lines ..." removed.txt' "hidden lines announced: $(cat removed.txt)"
expect '[ -z "$(grep " \.\.\.$" removed.txt | sort | uniq -d)" ]' "a stage announced twice: $(cat removed.txt)"
expect 'grep -q "strokes, pen down" removed.txt' "the summary on its own line: $(cat removed.txt)"
on_terminal haloed.txt 0 plot "$model" --halo 40 -o h.svg --gcode h.gcode
expect '[ "$(grep -c "^CUT: 100%" haloed.txt)" -eq 1 ]' "CUT's counter once: $(cat haloed.txt)"
expect '[ -z "$(grep " \.\.\.$" haloed.txt | sort | uniq -d)" ]' "a stage announced twice: $(cat haloed.txt)"
HALOPLOT_PROGRESS_AFTER_MS=0 "$tool" plot "$model" --halo 40 -o h.svg --gcode h.gcode 2> file.txt
expect '! grep -q -e " \.\.\.$" -e "CUT:" file.txt' "progress with stderr a file: $(cat file.txt)"
on_terminal quick.txt 600000 plot "$model" --mode hidden-removed -o q.svg --gcode q.gcode
expect '! grep -q " \.\.\.$" quick.txt' "a stage shorter than the wait announced: $(cat quick.txt)"
echo "progress: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
