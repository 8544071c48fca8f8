// The two limit switches: falling-edge interrupts on GPIO 0 pins 8 and 9 (board/pins.h), each
// calling on_trigger(motor) at the highest priority.
#pragma once
#include <stdint.h>

namespace haloplot::fw {

void limit_switches_init(void (*on_trigger)(uint8_t motor));

}  // namespace haloplot::fw
