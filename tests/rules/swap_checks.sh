#!/usr/bin/env bash
# Arguments that cannot be swapped silently: where a public entry takes two values side by side
# (an edge count and a crossing capacity, two flags, two callbacks, a point's coordinates, the
# board clock's tick rate and time scale), their
# types differ, so the swapped call is a compile error, not a run that reads the wrong memory.
# Each case is a small translation unit compiled (syntax only) against the real headers: the
# right form must build, the swapped (or the old two-values) form must not.
# Usage: swap_checks.sh SOURCE_DIR CXX
set -u
root=$1
cxx=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
pass=0 fail=0
flags=(-std=c++17 -fsyntax-only -ffreestanding -fno-exceptions -fno-rtti -I"$root/core/include" -I"$root/hal/include")

# try NAME ok|refused CODE
try() {
  local name=$1 expect=$2
  printf '%s\n' "$3" > "$work/$name.cpp"
  if "$cxx" "${flags[@]}" "$work/$name.cpp" 2> "$work/$name.err"; then
    if [ "$expect" = ok ]; then pass=$((pass + 1)); else
      fail=$((fail + 1)); echo "FAILED: $name built, but a swapped call must not"; fi
  elif [ "$expect" = refused ] && grep -q "error" "$work/$name.err"; then
    pass=$((pass + 1))
  else
    fail=$((fail + 1)); echo "FAILED: $name: expected it to build, got:"; head -5 "$work/$name.err"
  fi
}

job='#include "haloplot/job/job.h"
using namespace haloplot;
alignas(8) static unsigned char buf[4096];
static const Edge3 e[2] = {};
int f() {
  JobSpec spec; PreparedJob job; uint32_t cap = 0;
  Status s = Status::kOk;'
end='  return int(s);
}'
try job_prepare_right ok "$job
  s = job_prepare(spec, Edges{e, 2}, 16, buf, sizeof buf, &job, nullptr);
  s = job_prepare(spec, e, 16, buf, sizeof buf, &job, nullptr);  // the array's own count
$end"
try job_prepare_swapped refused "$job
  s = job_prepare(spec, 16, Edges{e, 2}, buf, sizeof buf, &job, nullptr);
$end"
try job_prepare_count_and_capacity refused "$job
  s = job_prepare(spec, e, 16u, 2u, buf, sizeof buf, &job, nullptr);
$end"
try job_crossings_right ok "$job
  s = job_crossings(spec, Edges{e, 2}, buf, sizeof buf, &cap);
$end"
try job_crossings_loose_count refused "$job
  s = job_crossings(spec, e, 2u, buf, sizeof buf, &cap);
$end"
try job_bytes_swapped refused "$job
  JobBytes b;
  s = job_bytes(spec, 16u, Edges{e, 2}, &b);
$end"
try job_redraw_count_and_capacity refused "$job
  s = job_redraw(spec, 16u, 2u, buf, sizeof buf, &job, nullptr);
$end"

band='#include "haloplot/band/conductor.h"
using namespace haloplot;
alignas(8) static unsigned char arena[4096];
Status f(BandConductor& c, const BandSpec& spec, BandStream stream) {'
try streamed_solid_flags ok "$band
  return c.begin_streamed_solid(spec, SolidStreamFlags::kClosed | SolidStreamFlags::kTurned, stream,
                                arena, sizeof arena);
}"
try streamed_solid_two_bools refused "$band
  return c.begin_streamed_solid(spec, true, false, stream, arena, sizeof arena);
}"

sink='#include "haloplot/solid/hidden_lines.h"
using namespace haloplot;
Status piece(void*, const HiddenPiece&) { return Status::kOk; }
Status outline(void*, const OutlinePiece&) { return Status::kOk; }'
try hidden_sink_right ok "$sink
HiddenSink s{nullptr, &piece, &outline, nullptr};
HiddenSink t{nullptr, &piece, nullptr, nullptr};"
try hidden_sink_swapped refused "$sink
HiddenSink s{nullptr, &outline, &piece, nullptr};"
try hidden_sink_piece_as_outline refused "$sink
HiddenSink s{nullptr, &piece, &piece, nullptr};"

path='#include "haloplot/motion/path_plan.h"
using namespace haloplot;
alignas(8) static unsigned char ws[4096];
Status f(Segment2* spans, PathPoint* out) {
  uint32_t count = 0;'
try plan_path_point ok "$path
  return plan_path(spans, 1, PenAt{3, 4}, ws, sizeof ws, out, 2, &count, nullptr);
}"
try plan_path_two_ints refused "$path
  return plan_path(spans, 1, 3, 4, ws, sizeof ws, out, 2, &count, nullptr);
}"

clock='#include "haloplot/hal/step_clock.h"
using namespace haloplot;'
try timer_init_right ok "$clock
struct B { static int timer_init(TickRate, TimeScale) { return 0; } };
static_assert(hal::HasTimerInit<B>::value, \"board\");
int f() { return B::timer_init(TickRate{1000}, TimeScale{1}); }"
try timer_init_swapped refused "$clock
struct B { static int timer_init(TickRate, TimeScale) { return 0; } };
int f() { return B::timer_init(TimeScale{1}, TickRate{1000}); }"
try timer_init_two_ints refused "$clock
struct B { static int timer_init(TickRate, TimeScale) { return 0; } };
int f() { return B::timer_init(1000u, 1u); }"
try timer_init_old_board refused "$clock
struct B { static int timer_init(uint32_t, uint32_t) { return 0; } };
static_assert(hal::HasTimerInit<B>::value, \"a board of two uint32_t is refused\");"

echo "swap_checks: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
