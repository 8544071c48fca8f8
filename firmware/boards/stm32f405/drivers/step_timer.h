// The step clock on SysTick, the core's 24-bit down-counter at 168 MHz. Its interrupt calls
// the motion's tick, which returns the ticks (Machine::tick_hz) to the next event; the
// interrupt turns them into core cycles with one multiply and restarts the counter for the
// period that has just begun, less the cycles the interrupt took to get there, so latency
// never accumulates. Delays beyond the counter's 2^24 cycles (pen dwells) run in chunks.
//
// Why SysTick and not TIM2: SysTick is part of the Cortex-M4, identical on every STM32 and
// modelled exactly by QEMU; QEMU 7.2's STM32 timer model never wraps its counter at ARR,
// so a timer-update step clock cannot be tested there.
#pragma once
#include <stdint.h>

#include "chip/stm32f405.h"
#include "haloplot/status/status.h"

namespace haloplot::fw {

// time_scale > 1 runs the clock that many times fast (test images under QEMU: the plot's
// ticks and trace are unchanged, only its wall time shrinks). kBadParameter unless the core
// clock is a whole multiple of tick_hz * time_scale.
Status step_timer_init(uint32_t tick_hz, uint32_t time_scale);
void step_timer_start(uint32_t first_delay);
void step_timer_stop();
// In the interrupt: true when a long delay's next chunk was armed (no event is due yet).
bool step_timer_chunk_pending();
void step_timer_next(uint32_t delay);  // arm the period that began with this interrupt

}  // namespace haloplot::fw
