// The step clock on the CMSDK APB timer 0, a 32-bit down-counter at the 25 MHz SYSCLK. Its
// interrupt acknowledges the timer and calls the controller's step interrupt, which returns
// the ticks (Machine::tick_hz) to the next event; step_timer_next() turns them into timer
// cycles with one multiply and reloads the counter for the period that has just begun, less
// the cycles since the interrupt fired, so latency never accumulates (the same scheme as the
// STM32F405's SysTick). Delays beyond 2^32 cycles (171 s) run in chunks.
//
// Why timer 0 and not SysTick: SysTick on this board would work too, but timer 0 is the
// board's own peripheral, with its own interrupt line and priority, and leaves SysTick to an
// RTOS a firmware author may bring.
#pragma once
#include <stdint.h>

#include "haloplot/status/status.h"

namespace haloplot::fw {

// kBadParameter unless the 25 MHz clock is a whole multiple of tick_hz * time_scale (test
// images run the clock time_scale times fast).
Status step_timer_init(uint32_t tick_hz, uint32_t time_scale);
void step_timer_start(uint32_t first_delay);
void step_timer_stop();
bool step_timer_chunk_pending();       // in the interrupt: a long delay's next chunk was armed
void step_timer_next(uint32_t delay);  // arm the period that began with this interrupt

}  // namespace haloplot::fw
