// A free-running counter for instruction counts under QEMU -icount shift=0 (every instruction
// advances the virtual clock by 1 ns) and for the link's frame timeout. Each board implements
// it with a timer the step clock does not use (boards/<board>/drivers/instruction_counter.cpp
// says which and at what rate): deterministic run to run, unlike SYS_ELAPSED, which QEMU
// answers from the host's clock.
#pragma once
#include <stdint.h>

namespace haloplot::fw {

void counter_start();      // free-running from 0
uint64_t counter_ticks();  // counts since counter_start(), extended past 32 bits in software
                           // (read at least once per 2^32 counts)
// Under QEMU -icount shift=0: the instructions a span of counts took (one count is a whole
// number of nanoseconds of virtual time, each 1 instruction).
uint64_t ticks_to_instructions(uint64_t ticks);

}  // namespace haloplot::fw
