// The independent watchdog: started once, kicked by every turn of the main loop, so a hung
// controller resets instead of holding the pen down. A board provides (board_hal.h):
//
//   struct MyBoard {
//     static void watchdog_start();
//     static void watchdog_kick();
//   };
#pragma once
#include "haloplot/hal/detect.h"

namespace haloplot::hal {

HALOPLOT_HAL_MEMBER(HasWatchdogStart, H::watchdog_start())
HALOPLOT_HAL_MEMBER(HasWatchdogKick, H::watchdog_kick())

template <typename B>
constexpr bool check_board_watchdog() {
  static_assert(HasWatchdogStart<B>::value, "the board has no static void watchdog_start()");
  static_assert(HasWatchdogKick<B>::value, "the board has no static void watchdog_kick()");
  return true;
}

}  // namespace haloplot::hal
