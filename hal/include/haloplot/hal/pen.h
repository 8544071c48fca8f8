// The pen lift: a hobby servo or a solenoid. The motion queue orders pen changes with the
// steps and waits travel + settle ticks after each (Machine::pen_travel_ticks,
// pen_settle_ticks), so the implementation only sets the position. The step tick calls it
// between steps, so it is part of the step HAL (a template parameter).
//
//   struct MyHal {
//     void pen(bool down);   // servo pulse width or solenoid pin
//   };
#pragma once
#include "haloplot/hal/detect.h"

namespace haloplot::hal {

HALOPLOT_HAL_MEMBER(HasPen, detail::object<H>().pen(false))

template <typename H>
constexpr bool check_pen() {
  static_assert(HasPen<H>::value,
                "this HAL has no void pen(bool down) (hal/include/haloplot/hal/pen.h)");
  return true;
}

// The board's side (board_hal.h): the servo or solenoid driver.
HALOPLOT_HAL_MEMBER(HasPenInit, H::pen_init())
HALOPLOT_HAL_MEMBER(HasPenSet, H::pen_set(false))

template <typename B>
constexpr bool check_board_pen() {
  static_assert(HasPenInit<B>::value, "the board has no static void pen_init()");
  static_assert(HasPenSet<B>::value, "the board has no static void pen_set(bool down)");
  return true;
}

}  // namespace haloplot::hal
