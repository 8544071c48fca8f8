// Run a whole motion plan in virtual time: the main loop (refill the segment queue) and the
// timer interrupt (tick) interleaved, the clock advanced by each delay the tick returns. The
// host simulator and the firmware self-test both drive the core with this one loop, so a
// difference between their traces can only come from the arithmetic of the two targets.
//
// Hal must provide `uint64_t now` (set here before each tick) besides the StepEngine calls
// (hal/step_clock.h, checked at compile time).
#pragma once
#include <stdint.h>

#include "motion/planner.h"
#include "motion/step_engine.h"
#include "motion/step_prep.h"
#include "step_clock.h"

namespace haloplot {

template <typename Hal, typename Queue>
Status run_virtual(MotionPlanner& planner, StepPrep& prep, Queue& queue, Hal& hal,
                   StepEngine<Hal, Queue>& engine) {
  static_assert(hal::check_virtual_clock<Hal>(), "run_virtual's HAL (hal/step_clock.h)");
  Status s = prep.fill(planner, queue);
  if (!ok(s)) return s;
  uint32_t delay = engine.start();
  while (delay != 0 || !queue.empty() || !prep.done()) {
    if (delay == 0) {  // the queue ran dry between moves: refill and resume
      s = prep.fill(planner, queue);
      if (!ok(s)) return s;
      delay = engine.start();
      if (delay == 0 && queue.empty() && prep.done()) break;
      continue;
    }
    hal.now += delay;
    s = prep.fill(planner, queue);
    if (!ok(s)) return s;
    delay = engine.tick();
  }
  return Status::kOk;
}

}  // namespace haloplot
