// What a board gives the portable controller (firmware/app: the job server's main loop and the
// motion runner, core/include/haloplot/controller/motion_runner.h): one type of static functions
// per board, one group per capability, each checked here at compile time with a message naming what
// is missing.
//
//   struct MyBoard {
//     static void init();            // clocks and pins; then the controller calls the rest
//     ... stepper_axis.h, pen.h, step_clock.h, serial.h, limit_switch.h, watchdog.h
//   };
//
// Static functions, not virtual ones: a board is chosen when the image is built, and the
// motion runner's step interrupt calls step_high() on every event, which must inline (the
// step HAL, plotter_hal.h, wraps these for the step tick). The rest could be virtual at no
// measurable cost, but one shape for the whole board reads better than two.
#pragma once
#include "haloplot/hal/detect.h"
#include "haloplot/hal/limit_switch.h"
#include "haloplot/hal/pen.h"
#include "haloplot/hal/serial.h"
#include "haloplot/hal/step_clock.h"
#include "haloplot/hal/stepper_axis.h"
#include "haloplot/hal/watchdog.h"

namespace haloplot::hal {

HALOPLOT_HAL_MEMBER(HasBoardInit, H::init())

// What the motion runner (core/include/haloplot/controller/motion_runner.h) calls: the stepper
// drivers, the pen and the step clock. The rest of a board is the main loop's, the integrator's to
// call.
template <typename B>
constexpr bool check_motion_board() {
  return check_board_stepper<B>() && check_board_pen<B>() && check_board_clock<B>();
}

template <typename B>
constexpr bool check_board() {
  static_assert(HasBoardInit<B>::value,
                "the board has no static void init() (hal/include/haloplot/hal/board_hal.h)");
  return check_motion_board<B>() && check_board_serial<B>() && check_board_limits<B>() &&
         check_board_watchdog<B>();
}

}  // namespace haloplot::hal
