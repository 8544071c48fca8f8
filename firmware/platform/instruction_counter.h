// Instruction counts under QEMU -icount shift=0, where every instruction advances the virtual
// clock by 1 ns. TIM5 (32 bits, prescaler 1) counts QEMU's timer clock, 1 GHz of virtual
// time: one count per instruction, exactly (a loop of 4,000,000 instructions reads 4,000,017: the
// loop plus the reads). Deterministic run to run, unlike SYS_ELAPSED, which QEMU answers from the
// host's clock. SysTick is not used: it is the step timer. On the chip TIM5 counts at 84 MHz
// instead (2 core cycles per count).
#pragma once
#include <stdint.h>

namespace haloplot::fw {

void counter_start();      // TIM5 free-running from 0
uint64_t counter_ticks();  // counts since counter_start(), extended past 32 bits in software
                           // (read at least once per 2^32 counts, 4.3 s of virtual time)
inline uint64_t ticks_to_instructions(uint64_t ticks) { return ticks; }

}  // namespace haloplot::fw
