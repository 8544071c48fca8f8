// TIM5 (32 bits, prescaler 1) counts QEMU's timer clock, 1 GHz of virtual time: one count per
// instruction, exactly (a loop of 4,000,000 instructions reads 4,000,017: the loop plus the
// reads). SysTick is not used: it is the step timer. On the chip TIM5 counts at 84 MHz instead
// (2 core cycles per count).
#include "platform/instruction_counter.h"

#include "chip/stm32f405.h"

namespace haloplot::fw {
namespace {
uint32_t last = 0, high = 0;  // the software extension of the 32-bit count
}

void counter_start() {
  using namespace chip;
  RCC.APB1ENR |= RCC_APB1ENR_TIM5EN;
  TIM5.CR1 = 0;
  TIM5.PSC = 0;
  TIM5.ARR = 0xFFFFFFFFu;
  TIM5.CNT = 0;
  TIM5.CR1 = TIM_CR1_CEN;
  last = high = 0;
}

uint64_t counter_ticks() {
  // Called from the main loop only (not reentrant): a smaller reading means one wrap.
  const uint32_t now = chip::TIM5.CNT;
  if (now < last) ++high;
  last = now;
  return uint64_t{high} << 32 | now;
}

uint64_t ticks_to_instructions(uint64_t ticks) { return ticks; }

}  // namespace haloplot::fw
