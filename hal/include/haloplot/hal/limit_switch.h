// End-stop switches, one per motor. A closed switch interrupts the controller, which stops the
// step timer at once and ends the plot with kLimitSwitch. A board provides (board_hal.h):
//
//   struct MyBoard {
//     static void limits_init(void (*on_trigger)(uint8_t motor));  // called from the interrupt
//   };
#pragma once
#include <stdint.h>

#include "haloplot/hal/detect.h"

namespace haloplot::hal {

HALOPLOT_HAL_MEMBER(HasLimitsInit, H::limits_init(static_cast<void (*)(uint8_t)>(nullptr)))

template <typename B>
constexpr bool check_board_limits() {
  static_assert(HasLimitsInit<B>::value,
                "the board has no static void limits_init(void (*on_trigger)(uint8_t motor))");
  return true;
}

}  // namespace haloplot::hal
