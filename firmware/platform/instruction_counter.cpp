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

}  // namespace haloplot::fw
