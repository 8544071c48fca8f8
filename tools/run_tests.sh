#!/usr/bin/env bash
# The README's test command: install what is missing, build every preset the tests need and
# run every test. CI runs exactly this (.ci/run).
#
# Two lanes run side by side, so neither core waits for the other's tail:
#   plain:     the firmware images (STM32F405, MPS2 AN385), the host build, then CTest on it:
#              unit tests, the tool, the package and the QEMU runs of both boards (the long
#              ones start first: their COST is set in tests/CMakeLists.txt);
#   sanitized: the host-asan build (clang, ASan + UBSan) and its CTest: every host test under
#              the sanitizers, and the libFuzzer targets built from the same sanitized library,
#              each replaying its seed corpus and exploring for a bounded time (the `fuzz`
#              preset builds those alone, for longer fuzzing).
# No test depends on the machine's speed (the QEMU link runs wait on the emulator's progress,
# not a clock), so the lanes may load both cores as they like.
#
# Usage: tools/run_tests.sh            everything (12 to 15 minutes on 2 cores)
#        ctest --preset host -L quick  the quick tests of an existing host build (a minute)
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install_deps.sh test
jobs=$(nproc)
# Page faults are dear on the virtual machines this runs on, and the test programs build and
# drop large arrays: glibc keeps freed memory for reuse rather than handing it back and
# faulting fresh pages in for the next one (the tool does the same in its main). A tenth of a
# test program's CPU time; the sanitizers' allocator ignores it.
export GLIBC_TUNABLES=glibc.malloc.mmap_threshold=33554432:glibc.malloc.trim_threshold=1073741824:glibc.malloc.top_pad=16777216
start=$SECONDS
logs=build/test-logs
mkdir -p "$logs"

say() { echo "== $1 ($((SECONDS - start)) s)"; }
# (errexit does not reach into a function run on the left of ||: each step returns its failure.)
build() {
  cmake --preset "$1" >/dev/null || return
  cmake --build --preset "$1" -j "$jobs"
}

plain_lane() {
  for preset in firmware firmware-mps2 host; do
    say "build: $preset"
    build "$preset" || return
  done
  say "ctest: host"
  ctest --preset host -j "$jobs"
}

sanitized_lane() {
  say "build: host-asan"
  build host-asan || return
  say "ctest: host-asan (the fuzz targets included)"
  ctest --preset host-asan -j "$jobs"
}

# The sanitized lane writes to its log; the plain lane to the terminal. Both logs are kept in
# build/test-logs/, and the sanitized one is printed whole once it ends.
sanitized_lane > "$logs/sanitized.log" 2>&1 &
sanitized_pid=$!
plain_rc=0
plain_lane 2>&1 | tee "$logs/plain.log" || plain_rc=$?
sanitized_rc=0
wait "$sanitized_pid" || sanitized_rc=$?
echo
echo "== the sanitized lane (build/test-logs/sanitized.log)"
cat "$logs/sanitized.log"
echo
say "done: plain lane exit $plain_rc, sanitized lane exit $sanitized_rc"
[ "$plain_rc" -eq 0 ] && [ "$sanitized_rc" -eq 0 ]
