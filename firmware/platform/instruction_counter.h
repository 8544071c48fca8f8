// Instruction counts under QEMU -icount shift=0, where every instruction advances the virtual
// clock by 1 ns. SysTick runs from the 168 MHz core clock on that virtual clock, so its ticks
// convert to instructions as ticks * 1000 / 168 (one tick is about 6 instructions: fine for
// counts in the thousands and above). Deterministic run to run, unlike SYS_ELAPSED, which
// QEMU answers from the host's clock. On the chip the same counter measures cycles / 1.
#pragma once
#include <stdint.h>

namespace haloplot::fw {

void counter_start();      // SysTick free-running, wraps counted by its interrupt
uint64_t counter_ticks();  // core-clock ticks since counter_start()
inline uint64_t ticks_to_instructions(uint64_t ticks) { return ticks * 1000 / 168; }

}  // namespace haloplot::fw
