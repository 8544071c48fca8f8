// The step clock. On a board it is a one-shot timer whose interrupt calls the step tick, which
// returns the delay to the next event in ticks (0: stop); see board_hal.h for the calls the
// controller makes. In virtual time (core/include/haloplot/motion/virtual_run.h: the simulator and
// the chip's self-tests) the clock is a counter on the step HAL that the run advances by each
// delay:
//
//   struct MyHal {
//     uint64_t now;   // ticks since the plot began; events are stamped with it
//   };
#pragma once
#include <stdint.h>

#include "haloplot/hal/detect.h"

namespace haloplot {

// The board's timer_init() takes its two numbers as two types, so a board or a caller that
// swaps them does not compile: the plan's ticks a second, and how many times fast the clock runs
// (1 on a plotter; more under emulation).
struct TickRate {
  uint32_t hz;
};
struct TimeScale {
  uint32_t factor;
};

}  // namespace haloplot

namespace haloplot::hal {

HALOPLOT_HAL_MEMBER(HasVirtualClock, detail::object<H>().now += uint32_t{1})

template <typename H>
constexpr bool check_virtual_clock() {
  static_assert(HasVirtualClock<H>::value,
                "this HAL has no uint64_t now: run_virtual stamps events with it "
                "(hal/include/haloplot/hal/step_clock.h)");
  return true;
}

// The board's one-shot step timer (board_hal.h). A delay longer than the timer's reach runs in
// chunks; timer_chunk_pending() says the interrupt is such a chunk, not yet the tick's.
HALOPLOT_HAL_MEMBER(HasTimerInit, H::timer_init(TickRate{1}, TimeScale{1}))
HALOPLOT_HAL_MEMBER(HasTimerStart, H::timer_start(uint32_t{1}))
HALOPLOT_HAL_MEMBER(HasTimerNext, H::timer_next(uint32_t{1}))
HALOPLOT_HAL_MEMBER(HasTimerStop, H::timer_stop())
HALOPLOT_HAL_MEMBER(HasTimerChunk, static_cast<bool>(H::timer_chunk_pending()))

template <typename B>
constexpr bool check_board_clock() {
  static_assert(HasTimerInit<B>::value,
                "the board has no static Status timer_init(TickRate tick, TimeScale scale)");
  static_assert(HasTimerStart<B>::value,
                "the board has no static void timer_start(uint32_t first_delay)");
  static_assert(HasTimerNext<B>::value, "the board has no static void timer_next(uint32_t delay)");
  static_assert(HasTimerStop<B>::value, "the board has no static void timer_stop()");
  static_assert(HasTimerChunk<B>::value, "the board has no static bool timer_chunk_pending()");
  return true;
}

}  // namespace haloplot::hal
