#!/usr/bin/env bash
# The HAL's compile-time checks must see what they guard: a step HAL or a board that lacks a
# member must fail to build, with a message that names the member; a complete one must build.
# Each case is a small translation unit compiled (syntax only) against the real headers.
# Usage: hal_checks.sh SOURCE_DIR CXX   (the headers from core/include and hal/include)
set -u
root=$1
cxx=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
pass=0 fail=0
flags=(-std=c++17 -fsyntax-only -ffreestanding -fno-exceptions -fno-rtti -I"$root/core/include" -I"$root/hal/include")

# try NAME EXPECT CODE: EXPECT is "ok" or the text the error must contain.
try() {
  local name=$1 expect=$2
  printf '%s\n' "$3" > "$work/$name.cpp"
  if "$cxx" "${flags[@]}" "$work/$name.cpp" 2> "$work/$name.err"; then
    if [ "$expect" = ok ]; then pass=$((pass + 1)); else
      fail=$((fail + 1)); echo "FAILED: $name built, but should fail with: $expect"; fi
  elif [ "$expect" != ok ] && grep -qF -- "$expect" "$work/$name.err"; then
    pass=$((pass + 1))
  else
    fail=$((fail + 1)); echo "FAILED: $name: expected '$expect', got:"; head -5 "$work/$name.err"
  fi
}

engine='#include "haloplot/motion/step_engine.h"
#include "haloplot/motion/step_segment.h"
using namespace haloplot;'
full='void step(uint8_t) {} void set_direction(uint8_t, bool) {} void pen(bool) {}'
try step_hal_complete ok "$engine
struct H { $full };
SegmentQueue<4> q; H h; StepEngine<H, SegmentQueue<4>> e(h, q);"
try step_hal_no_step "has no void step(uint8_t motor)" "$engine
struct H { void set_direction(uint8_t, bool) {} void pen(bool) {} };
SegmentQueue<4> q; H h; StepEngine<H, SegmentQueue<4>> e(h, q);"
try step_hal_no_direction "has no void set_direction(uint8_t motor, bool backward)" "$engine
struct H { void step(uint8_t) {} void pen(bool) {} };
SegmentQueue<4> q; H h; StepEngine<H, SegmentQueue<4>> e(h, q);"
try step_hal_no_pen "has no void pen(bool down)" "$engine
struct H { void step(uint8_t) {} void set_direction(uint8_t, bool) {} };
SegmentQueue<4> q; H h; StepEngine<H, SegmentQueue<4>> e(h, q);"
try virtual_run_no_clock "has no uint64_t now" "#include \"haloplot/motion/virtual_run.h\"
using namespace haloplot;
struct H { $full };
Status run(MotionPlanner& p, StepPrep& s, SegmentQueue<4>& q, H& h, StepEngine<H, SegmentQueue<4>>& e) {
  return run_virtual(p, s, q, h, e);
}
template Status run_virtual(MotionPlanner&, StepPrep&, SegmentQueue<4>&, H&, StepEngine<H, SegmentQueue<4>>&);"

# A board: every capability, then each group with one function taken out.
board_fns=(
  'static void init() {}'
  'static void step_high(uint8_t) {}' 'static void steps_low() {}'
  'static void set_dir(uint8_t, bool) {}' 'static void enable_drivers(bool) {}'
  'static void pen_init() {}' 'static void pen_set(bool) {}'
  'static int timer_init(haloplot::TickRate, haloplot::TimeScale) { return 0; }' 'static void timer_start(uint32_t) {}'
  'static void timer_next(uint32_t) {}' 'static void timer_stop() {}'
  'static bool timer_chunk_pending() { return false; }'
  'static void serial_init(uint32_t) {}' 'static bool serial_read(uint8_t*) { return false; }'
  'static void serial_write(const uint8_t*, uint32_t) {}' 'static uint32_t serial_overruns() { return 0; }'
  'static void limits_init(void (*)(uint8_t)) {}'
  'static void watchdog_start() {}' 'static void watchdog_kick() {}'
)
board() {  # board SKIP: the board without function number SKIP (-1: complete)
  local body="" i
  for i in "${!board_fns[@]}"; do [ "$i" -eq "$1" ] || body+="${board_fns[$i]} "; done
  printf '#include "haloplot/hal/board_hal.h"\n#include <stdint.h>\nstruct B { %s };\nstatic_assert(haloplot::hal::check_board<B>(), "board");\n' "$body"
}
try board_complete ok "$(board -1)"
try board_no_step_high "has no static void step_high(uint8_t motor)" "$(board 1)"
try board_no_pen_set "has no static void pen_set(bool down)" "$(board 6)"
try board_no_timer_stop "has no static void timer_stop()" "$(board 10)"
try board_no_serial_read "has no static bool serial_read(uint8_t* byte)" "$(board 13)"
try board_no_limits "has no static void limits_init" "$(board 16)"
try board_no_watchdog_kick "has no static void watchdog_kick()" "$(board 18)"

echo "hal_checks: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
