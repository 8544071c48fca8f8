// GPIO 0 set-up and the step/direction/enable/pen pins. Every pin write is one masked store
// (no read-modify-write that an interrupt could tear), because the step tick calls them on
// every event.
#pragma once
#include <stdint.h>

#include "board/pins.h"
#include "chip/cmsdk.h"

namespace haloplot::fw {

void gpio_init();  // outputs low (drivers disabled, pen up), limit inputs

inline void step_pin_high(uint8_t motor) {
  const uint32_t bit = 1u << board::kStepPin[motor];
  chip::gpio_masked(chip::kGpio0Base, bit) = bit;
}
// Both STEP pins low: at the start of every timer interrupt, so a pulse lasts one interval.
inline void step_pins_low() {
  chip::gpio_masked(chip::kGpio0Base, (1u << board::kStepPin[0]) | (1u << board::kStepPin[1])) = 0;
}
inline void dir_pin(uint8_t motor, bool backward) {
  const uint32_t bit = 1u << board::kDirPin[motor];
  chip::gpio_masked(chip::kGpio0Base, bit) = backward ? bit : 0;
}
inline void drivers_enable(bool on) {  // ENABLE is active low
  const uint32_t bit = 1u << board::kEnablePin;
  chip::gpio_masked(chip::kGpio0Base, bit) = on ? 0 : bit;
}
inline void pen_solenoid(bool down) {
  const uint32_t bit = 1u << board::kPenPin;
  chip::gpio_masked(chip::kGpio0Base, bit) = down ? bit : 0;
}

}  // namespace haloplot::fw
