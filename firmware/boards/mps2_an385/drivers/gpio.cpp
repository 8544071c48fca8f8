#include "drivers/gpio.h"

namespace haloplot::fw {

void gpio_init() {
  using namespace chip;
  step_pins_low();
  drivers_enable(false);
  pen_solenoid(false);
  uint32_t outputs = (1u << board::kEnablePin) | (1u << board::kPenPin);
  for (uint8_t m = 0; m < hal::kMotors; ++m)
    outputs |= (1u << board::kStepPin[m]) | (1u << board::kDirPin[m]);
  GPIO0.OUTENSET = outputs;
  GPIO0.ALTFUNCCLR = outputs | (1u << board::kLimitPin[0]) | (1u << board::kLimitPin[1]);
}

}  // namespace haloplot::fw
