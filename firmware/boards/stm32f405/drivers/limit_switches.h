// Limit switches on EXTI0 and EXTI1 (falling edge: the switch closes to ground). The
// interrupt stops the step timer at once, before the main loop hears of it, and records
// which switch fired; the motion then ends with kLimitSwitch.
#pragma once
#include <stdint.h>

namespace haloplot::fw {

// on_trigger runs inside the interrupt: it must stop motion and return.
void limit_switches_init(void (*on_trigger)(uint8_t motor));

}  // namespace haloplot::fw
