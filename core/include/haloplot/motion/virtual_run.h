// Run a whole motion plan in virtual time: the main loop (refill the segment queue) and the
// timer interrupt (tick) interleaved, the clock advanced by each delay the tick returns. The
// host simulator and the firmware self-test both drive the core with this one loop, so a
// difference between their traces can only come from the arithmetic of the two targets.
//
// Hal must provide `uint64_t now` (set here before each tick) besides the StepEngine calls
// (hal/include/haloplot/hal/step_clock.h, checked at compile time).
#pragma once
#include <stdint.h>

#include "haloplot/hal/step_clock.h"
#include "haloplot/motion/planner.h"
#include "haloplot/motion/step_engine.h"
#include "haloplot/motion/step_prep.h"

namespace haloplot {

// Feed holds to make during the run (a pause button pressed at these moments): a hold is
// asked for once the tick has made at_events[k] step events (ascending), and resumed as soon
// as it is at rest with its pen lifted. The wait itself is wall time on a controller; in
// virtual time it takes none, so a held plot's trace differs from the unpaused one only by
// the braking, the pen lift and lowering, and the start from rest.
struct HoldSchedule {
  const uint32_t* at_events = nullptr;
  uint32_t n = 0;
};

// Make a plot's first `events` step events again with no motor moving, then restart it from
// there (StepPrep::restart_at): what a controller does to go on with a plot that stopped after
// that many events (an abort, a reset), drawing nothing twice. One segment is kept in flight,
// so the prep's last segment is the one the tick stopped in; a backlash take-up is run out
// (it moves no carriage). kUnsupported for a plot whose points are still arriving (a streamed
// one): it cannot be made again without them.
struct SilentHal {
  void step(uint8_t) {}
  void set_direction(uint8_t, bool) {}
  void pen(bool) {}
};

inline Status skip_events(MotionPlanner& planner, StepPrep& prep, uint32_t events) {
  if (events == 0) return Status::kOk;
  SilentHal hal;
  SegmentQueue<2> queue;
  StepEngine<SilentHal, SegmentQueue<2>> engine(hal, queue);
  while (engine.events() < events || (prep.in_takeup() && engine.remaining() > 0)) {
    if (engine.remaining() > 0) {
      (void)engine.tick();
      continue;
    }
    bool pushed = false;
    const Status s = prep.fill_one(planner, queue, &pushed);
    if (!ok(s)) return s;
    if (!pushed) {
      if (prep.done()) break;  // the plot ended before: nothing left to draw
      return Status::kUnsupported;
    }
    (void)engine.start();
  }
  const int32_t motors[2] = {engine.position(0), engine.position(1)};
  if (!prep.done()) prep.restart_at(engine.remaining(), motors);
  return Status::kOk;
}

template <typename Hal, typename Queue>
Status run_virtual(MotionPlanner& planner, StepPrep& prep, Queue& queue, Hal& hal,
                   StepEngine<Hal, Queue>& engine, HoldSchedule holds = {}) {
  static_assert(hal::check_virtual_clock<Hal>(),
                "run_virtual's HAL (hal/include/haloplot/hal/step_clock.h)");
  uint32_t next_hold = 0;
  Status s = prep.fill(planner, queue);
  if (!ok(s)) return s;
  uint32_t delay = engine.start();
  while (delay != 0 || !queue.empty() || !prep.done()) {
    if (delay == 0) {  // the queue ran dry between moves: refill and resume
      if (prep.held() && queue.empty()) prep.resume();  // the hold is at rest: go on
      s = prep.fill(planner, queue);
      if (!ok(s)) return s;
      delay = engine.start();
      if (delay == 0 && queue.empty() && prep.done()) break;
      continue;
    }
    hal.now += delay;
    s = prep.fill(planner, queue);
    if (!ok(s)) return s;
    // A hold is asked for between a refill and the next tick, as the controller's main loop
    // asks for one (motion_runner.h, pause()): from the end of a full queue.
    if (next_hold < holds.n && engine.events() >= holds.at_events[next_hold] && !prep.holding()) {
      prep.hold();
      ++next_hold;
    }
    delay = engine.tick();
  }
  return Status::kOk;
}

}  // namespace haloplot
