// GPIO set-up and the step/direction/enable pins. The pin writes are inline single stores to
// BSRR (atomic set or reset, no read-modify-write), because the step tick calls them on
// every event.
#pragma once
#include <stdint.h>

#include "board/pins.h"
#include "chip/stm32f405.h"

namespace haloplot::fw {

void gpio_init();  // clocks, modes, pulls and alternate functions for every pin in board/

inline void step_pin_high(uint8_t motor) { chip::GPIOD.BSRR = 1u << board::kStepPin[motor]; }
// Both STEP pins low: at the start of every timer interrupt, so a pulse lasts one interval
// (at least the timer floor, far above a driver's minimum pulse width).
inline void step_pins_low() {
  chip::GPIOD.BSRR = (1u << (board::kStepPin[0] + 16)) | (1u << (board::kStepPin[1] + 16));
}
inline void dir_pin(uint8_t motor, bool backward) {
  chip::GPIOD.BSRR = 1u << (board::kDirPin[motor] + (backward ? 0 : 16));
}
inline void drivers_enable(bool on) {  // ENABLE is active low
  chip::GPIOD.BSRR = 1u << (board::kEnablePin + (on ? 16 : 0));
}
inline bool limit_input_active(uint8_t motor) {  // switch closed pulls the pin low
  return (chip::GPIOE.IDR & (1u << board::kLimitPin[motor])) == 0;
}

}  // namespace haloplot::fw
