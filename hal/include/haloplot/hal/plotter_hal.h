// The interface the step engine drives, composed from the capability interfaces: the
// stepper axes (stepper_axis.h) and the pen (pen.h). The firmware, the simulator's recording
// HAL, the self-tests and the benchmarks each provide one such class; StepEngine<Hal> checks
// it at compile time (check_plotter_hal) and inlines it.
//
//   struct PlotterHal {
//     void step(uint8_t motor);
//     void set_direction(uint8_t motor, bool backward);
//     void pen(bool down);
//   };
//
// Why templates and not virtual functions: a step event must cost a few dozen instructions
// (the goal is at most 60). An indirect call per pin write, through a vtable the compiler
// cannot see through, costs more than the Bresenham step itself and blocks inlining.
// What is not on the step path (serial, limit switches, watchdog, the timer) is the board's
// (board_hal.h), checked the same way.
#pragma once
#include "haloplot/hal/pen.h"
#include "haloplot/hal/step_clock.h"
#include "haloplot/hal/stepper_axis.h"

namespace haloplot::hal {

template <typename H>
constexpr bool check_plotter_hal() {
  return check_stepper_axes<H>() && check_pen<H>();
}

}  // namespace haloplot::hal
