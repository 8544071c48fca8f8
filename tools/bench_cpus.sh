#!/usr/bin/env bash
# Instructions per CPU under QEMU -icount (one instruction per nanosecond of virtual time): CUT
# on the EDGE rows and Figure 4's CUT + DRAW in bands (tests/firmware/cpu_bench), for the
# Cortex-M0+ (ARMv6-M: no 32 x 32 -> 64 multiply), M4 and M33, and RV32IMAC where its compiler
# and emulator are installed. Each CPU: the core built and installed with a toolchain file of
# its own (as a user builds it, MinSizeRel with the hot files at -O2), the benchmark linked
# against it. The Arm images run on mps2-an386 (a Cortex-M4 that runs M0+ and M33 code alike:
# none uses an instruction beyond ARMv7E-M), the RV32 one on virt. The counts are of the code
# each CPU's compiler emits; cycles differ (the M0+'s MULS and loads take what its core says).
# Where the M0+'s instructions go: a histogram by function of one run of each image (QEMU's
# in_asm and exec logs: every translated block's instructions times its executions).
# With --baseline REV, the same for the source at git revision REV, side by side in one run.
# Writes section "12. Instructions per CPU" of docs/reports/performance.md in place (or prints
# it with --print). Usage: tools/bench_cpus.sh [--print] [--baseline REV]
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
print=0
baseline=""
while [ $# -gt 0 ]; do
  case "$1" in
    --print) print=1 ;;
    --baseline) baseline=$2; shift ;;
    *) echo "usage: $0 [--print] [--baseline REV]" >&2; exit 2 ;;
  esac
  shift
done
command -v qemu-system-arm >/dev/null && command -v arm-none-eabi-g++ >/dev/null ||
  { echo "bench_cpus: needs qemu-system-arm and arm-none-eabi-g++" >&2; exit 1; }
cpus="M0+ M4 M33"
if command -v qemu-system-riscv32 >/dev/null && command -v riscv64-unknown-elf-g++ >/dev/null; then
  cpus="$cpus RV32"
else
  echo "bench_cpus: no qemu-system-riscv32 or riscv64-unknown-elf-g++: RV32 left out" >&2
fi
out=$root/build/cpu_bench
mkdir -p "$out"
source tests/firmware/qemu_run.sh

toolchain() {  # CPU: its toolchain file's path
  local cpu=$1 flags
  case "$cpu" in
    RV32) echo "$root/cmake/rv32imac.cmake"; return ;;
    M0+) flags="-mcpu=cortex-m0plus -mthumb -mfloat-abi=soft" ;;
    M4) flags="-mcpu=cortex-m4 -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16" ;;
    M33) flags="-mcpu=cortex-m33 -mthumb -mfloat-abi=hard -mfpu=fpv5-sp-d16" ;;
  esac
  cat > "$out/$cpu.cmake" <<TOOLCHAIN
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR arm)
set(CMAKE_C_COMPILER arm-none-eabi-gcc)
set(CMAKE_CXX_COMPILER arm-none-eabi-g++)
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)
set(CMAKE_C_FLAGS_INIT "$flags -ffunction-sections -fdata-sections")
set(CMAKE_CXX_FLAGS_INIT "$flags -ffunction-sections -fdata-sections")
TOOLCHAIN
  echo "$out/$cpu.cmake"
}

# build SRC TAG CPU: the core for CPU from source tree SRC, installed, and the benchmark images
# in $out/TAG/CPU/bench.
build() {
  local src=$1 dir=$out/$2/$3 chain
  chain=$(toolchain "$3")
  mkdir -p "$dir"
  { cmake -S "$src" -B "$dir/lib" -DCMAKE_TOOLCHAIN_FILE="$chain" -DCMAKE_BUILD_TYPE=MinSizeRel &&
    cmake --build "$dir/lib" --target haloplot_core -j2 &&
    cmake --install "$dir/lib" --prefix "$dir/prefix" &&
    cmake -S "$root/tests/firmware/cpu_bench" -B "$dir/bench" -DCMAKE_TOOLCHAIN_FILE="$chain" \
      -DCMAKE_PREFIX_PATH="$dir/prefix" -DHALOPLOT_SOURCE_DIR="$root" -DCMAKE_BUILD_TYPE=MinSizeRel &&
    cmake --build "$dir/bench" -j2; } > "$dir/build.log" 2>&1 ||
    { tail -30 "$dir/build.log" >&2; echo "bench_cpus: the $3 build ($2) failed" >&2; exit 1; }
}

machine() { if [ "$1" = RV32 ]; then echo virt; else echo mps2-an386; fi; }

# run TAG CPU: the images' output lines in $out/TAG/CPU/{cut,fig4,draw}.out
run() {
  local dir=$out/$1/$2 part
  for part in cut fig4 draw; do
    qemu_run "$(machine "$2")" "$dir/bench/cpu_bench_$part.elf" > "$dir/$part.out" ||
      { cat "$dir/$part.out" >&2; echo "bench_cpus: the $2 $part run failed" >&2; exit 1; }
  done
}

# profile TAG CPU PART: where the instructions between bench_span_begin() and bench_span_end()
# go in one run of the PART image (QEMU's in_asm log gives each translated block's instructions,
# its exec log each execution with the function's name). Writes $out/TAG/CPU/PART.profile:
#   "total N", "self SHARE FUNCTION" per function, and per library routine called from the
#   core ("__" names, libgcc's: the 64-bit multiply, division and shifts the CPU lacks)
#   "lib SHARE ROUTINE CALLER CALLS": its instructions, with those of the routines it calls,
#   and its calls, charged to the function that called it.
profile() {
  local dir=$out/$1/$2 fifo
  fifo=$(mktemp -u)
  mkfifo "$fifo"
  awk '
    /^IN: / { name = $2; next }
    /^0x[0-9a-f]+:/ { if (start == "") start = $1; n++; next }
    /^$/ { if (start != "") { sub(":", "", start); size[start] = n; fn[start] = name } start = ""; n = 0; next }
    /^Trace / {
      pc = $0; sub(/.*\[[0-9a-f]+\//, "", pc); sub(/\/.*/, "", pc); pc = "0x" pc
      f = fn[pc]
      if (f == "bench_span_begin") on = 1
      if (f == "bench_span_end") on = 0
      if (!on) next
      t = size[pc]; total += t; self[f] += t
      if (substr(f, 1, 2) == "__") {
        if (routine == "") { routine = f; calls[routine SUBSEP owner]++ }
        lib[routine SUBSEP owner] += t
      } else { owner = f; routine = "" }
    }
    END {
      printf "total %d\n", total
      for (f in self) printf "self %.4f %s\n", self[f] / total, f
      for (k in lib) { split(k, p, SUBSEP); printf "lib %.4f %s %s %d\n", lib[k] / total, p[1], p[2], calls[k] }
    }' "$fifo" > "$dir/$3.profile" &
  local reader=$!
  qemu_run "$(machine "$2")" "$dir/bench/cpu_bench_$3.elf" -d in_asm,exec,nochain -D "$fifo" \
    > /dev/null
  wait "$reader"
  rm -f "$fifo"
}

tags="now"
  for cpu in $cpus; do build "$root" now "$cpu"; done
if [ -n "$baseline" ]; then
  rev=$(git rev-parse "$baseline")
  if [ "$(cat "$out/src-base.rev" 2>/dev/null)" != "$rev" ]; then  # kept for the next run
    rm -rf "$out/src-base"
    mkdir -p "$out/src-base"
    git archive "$rev" | tar -x -C "$out/src-base"
    echo "$rev" > "$out/src-base.rev"
  fi
  for cpu in $cpus; do build "$out/src-base" base "$cpu"; done
  tags="base now"
fi
for tag in $tags; do
  for cpu in $cpus; do run "$tag" "$cpu"; done
  profile "$tag" M0+ cut
  profile "$tag" M0+ draw
done

# The section: the counts, checked equal in what they count on every CPU and both sources (the
# crossings of each row; Figure 4's bands, pieces and records), then the tables.
section() {
  python3 - "$out" "$baseline" $cpus <<'PY'
import subprocess, sys
out, baseline, cpus = sys.argv[1], sys.argv[2], sys.argv[3:]
tags = ["base", "now"] if baseline else ["now"]
def lines(tag, cpu, part):
    return [l.split()[2:] for l in open(f"{out}/{tag}/{cpu}/{part}.out") if l.startswith("fw ")]
rows = {(t, c): [list(map(int, r)) for r in lines(t, c, "cut")] for t in tags for c in cpus}
fig4 = {(t, c): list(map(int, lines(t, c, "fig4")[0])) for t in tags for c in cpus}
draw = {(t, c): list(map(int, lines(t, c, "draw")[0])) for t in tags for c in cpus}
for k, v in draw.items():
    if v[:2] != draw[("now", cpus[0])][:2]:
        sys.exit(f"bench_cpus: 20 x 20 cubes on {k}: other crossings or spans")
ref = rows[("now", cpus[0])]
for k, v in rows.items():
    if [r[:4] + r[5:] for r in v] != [r[:4] + r[5:] for r in ref]:
        sys.exit(f"bench_cpus: CUT on {k} found other crossings than on {cpus[0]}")
for k, v in fig4.items():
    if v[:3] != fig4[("now", cpus[0])][:3]:
        sys.exit(f"bench_cpus: Figure 4 on {k}: other bands, pieces or records")
def n(v): return f"{v:,}"
def ratio(a, b): return f"{a / b:.2f}"
print("## 12. Instructions per CPU (QEMU -icount)")
print()
print("Generated by `bash tools/bench_cpus.sh" + (f" --baseline {baseline}" if baseline else "") + "`: the core built for each CPU")
print("with a toolchain file of its own (MinSizeRel, CUT, DRAW and the bands at -O2, as the")
print("firmware builds them) and the benchmark of tests/firmware/cpu_bench linked against it, run")
print("under QEMU with -icount (one instruction per nanosecond of virtual time; the Arm images on")
print("mps2-an386, whose Cortex-M4 runs the M0+ and M33 code alike, RV32IMAC on virt). These are")
print("instruction counts of each CPU's code, exact to the 40-instruction tick of the Arm counter;")
print("cycles differ by core. Every CPU finds the same crossings on every row and the same bands,")
print("pieces and records on Figure 4 (the script checks; the M4's crossings are the host's, CTest")
print("firmware_cut_bench, and its Figure 4 trace is, firmware_bands).")
print()
print("CUT on the EDGE rows (section 8's scenes and seeds), instructions:")
print()
print("| N | L | crossings | " + " | ".join(cpus) + " | M0+ / M4 |")
print("|---:|---:|---:|" + "---:|" * len(cpus) + "---:|")
for i, r in enumerate(ref):
    cells = [n(rows[("now", c)][i][4]) for c in cpus]
    print(f"| {r[0]} | {r[1] / 1e6:.2f} | {r[3]} | " + " | ".join(cells) +
          f" | {ratio(rows[('now', 'M0+')][i][4], rows[('now', 'M4')][i][4])} |")
print()
print("Figure 4 in bands in a 64 KB arena (9,408 edges, halo 50; "
      f"{fig4[('now', cpus[0])][0]} bands), instructions:")
print()
print("| | " + " | ".join(cpus) + " | M0+ / M4 |")
print("|---|" + "---:|" * len(cpus) + "---:|")
for name, f in (("CUT", lambda v: v[3]), ("DRAW", lambda v: v[4]), ("CUT + DRAW", lambda v: v[3] + v[4]),
                ("the margin pass (CUT in bands, once)", lambda v: v[5])):
    print(f"| {name} | " + " | ".join(n(f(fig4[("now", c)])) for c in cpus) +
          f" | {ratio(f(fig4[('now', 'M0+')]), f(fig4[('now', 'M4')]))} |")
if baseline:
    print()
    print(f"Before (the core at {baseline}) and now, the same benchmark:")
    print()
    print("| CPU | CUT, EDGE rows, before | now | now / before | Figure 4 CUT + DRAW, before | now | now / before |")
    print("|---|---:|---:|---:|---:|---:|---:|")
    for c in cpus:
        b = sum(r[4] for r in rows[("base", c)]); a = sum(r[4] for r in rows[("now", c)])
        fb = fig4[("base", c)][3] + fig4[("base", c)][4]; fa = fig4[("now", c)][3] + fig4[("now", c)][4]
        print(f"| {c} | {n(b)} | {n(a)} | {ratio(a, b)} | {n(fb)} | {n(fa)} | {ratio(fa, fb)} |")
    mb = sum(r[4] for r in rows[("base", "M0+")]) / sum(r[4] for r in rows[("base", "M4")])
    ma = sum(r[4] for r in rows[("now", "M0+")]) / sum(r[4] for r in rows[("now", "M4")])
    print()
    print(f"The M0+ takes {mb:.2f} times the M4's instructions for CUT on these rows before, {ma:.2f} now.")
print()
print("DRAW alone: 20 x 20 cubes seen as Figure 4 (4,800 edges, halo 50, the paper's gap) in one")
print(f"piece, {n(draw[('now', cpus[0])][0])} crossings, {n(draw[('now', cpus[0])][1])} spans; instructions:")
print()
print("| | " + " | ".join(cpus) + " | M0+ / M4 |")
print("|---|" + "---:|" * len(cpus) + "---:|")
for tag in tags:
    for name, i in (("CUT", 2), ("DRAW", 3)):
        label = name + (", before" if tag == "base" else "")
        print(f"| {label} | " + " | ".join(n(draw[(tag, c)][i]) for c in cpus) +
              f" | {ratio(draw[(tag, 'M0+')][i], draw[(tag, 'M4')][i])} |")
def profile(tag, part):
    total, self, lib = 0, {}, {}
    for l in open(f"{out}/{tag}/M0+/{part}.profile"):
        f = l.split()
        if f[0] == "total": total = int(f[1])
        elif f[0] == "self": self[f[2]] = float(f[1])
        elif f[0] == "lib": lib[(f[2], f[3])] = (float(f[1]), int(f[4]))
    return total, self, lib
def short(sym):
    name = subprocess.run(["c++filt", sym], capture_output=True, text=True).stdout.strip()
    name = name.replace("(anonymous namespace)::", "").replace("haloplot::", "")
    depth, plain = 0, ""
    for ch in name:  # template arguments dropped
        depth += ch == "<"
        if depth == 0: plain += ch
        depth -= ch == ">"
    plain = plain.split("(")[0].split()  # the arguments and the return type dropped
    return "`" + (plain[-1] if plain else sym) + "`"
def when(t): return "before" if t == "base" else "now"
for part, what in (("cut", "CUT on the EDGE rows"), ("draw", "DRAW of the 20 x 20 cubes")):
    print()
    print(f"Where the M0+'s instructions go in {what} (one run; QEMU's in_asm and exec logs between")
    print("the benchmark's marks, by function, each function's own instructions; `__aeabi_lmul` and")
    print("`__muldi3` are libgcc's 64 x 64 multiply, which ARMv6-M, with MULS only, calls;")
    print("`__aeabi_*div*` and `__*divdi3` its divisions, which it has no instruction for at any width):")
    print()
    runs = [(t, profile(t, part)) for t in tags]
    names = {k for k in ("__aeabi_lmul", "__muldi3") if any(r[1][1].get(k, 0) for r in runs)}
    for t, (total, self, lib) in runs:
        names |= {k for k, v in sorted(self.items(), key=lambda kv: -kv[1])[:8]}
    print("| function | " + " | ".join("share, " + when(t) for t in tags) + " |")
    print("|---|" + "---:|" * len(tags))
    for k in sorted(names, key=lambda k: -max(r[1][1].get(k, 0) for r in runs)):
        print(f"| {short(k)} | " + " | ".join(f"{100 * r[1][1].get(k, 0):.1f} %" for r in runs) + " |")
    print("| instructions | " + " | ".join(n(r[1][0]) for r in runs) + " |")
    print()
    print("Library calls by caller, the largest (calls, and the routine's instructions with the")
    print("routines it calls as shares of the run):")
    print()
    print("| routine | caller | " + " | ".join(when(t) for t in tags) + " |")
    print("|---|---|" + "---:|" * len(tags))
    keys = {k for t, (total, self, lib) in runs for k in lib}
    keys = sorted(keys, key=lambda k: -max(r[1][2].get(k, (0, 0))[0] for r in runs))
    for k in keys[:8]:
        cells = []
        for t, (total, self, lib) in runs:
            share, calls = lib.get(k, (0, 0))
            cells.append(f"{n(calls)} ({100 * share:.1f} %)")
        print(f"| `{k[0]}` | {short(k[1])} | " + " | ".join(cells) + " |")
PY
}
section > "$out/section.md"
if [ "$print" = 1 ]; then cat "$out/section.md"; exit 0; fi
doc=docs/reports/performance.md
awk -v file="$out/section.md" '
  /^## 12\. Instructions per CPU/ { while ((getline l < file) > 0) print l; skip = 1; next }
  skip && /^## / { skip = 0 }
  !skip { print }
  ' "$doc" > "$out/perf.md"
grep -q '^## 12\. Instructions per CPU' "$doc" || { echo; cat "$out/section.md"; } >> "$out/perf.md"
cp "$out/perf.md" "$doc"
cat "$out/section.md"
