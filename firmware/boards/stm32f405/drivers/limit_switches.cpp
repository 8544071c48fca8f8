#include "drivers/limit_switches.h"

#include "board/pins.h"
#include "chip/stm32f405.h"

namespace haloplot::fw {
namespace {
void (*handler)(uint8_t) = nullptr;
}

void limit_switches_init(void (*on_trigger)(uint8_t motor)) {
  using namespace chip;
  handler = on_trigger;
  RCC.APB2ENR |= RCC_APB2ENR_SYSCFGEN;
  for (uint8_t m = 0; m < hal::kMotors; ++m) {
    const uint32_t line = board::kLimitPin[m];
    // EXTICR selects the port for each line: 4 = port E.
    SYSCFG.EXTICR[line / 4] =
        (SYSCFG.EXTICR[line / 4] & ~(0xFu << (4 * (line % 4)))) | (4u << (4 * (line % 4)));
    EXTI.FTSR |= 1u << line;
    EXTI.IMR |= 1u << line;
  }
  nvic_priority(kExti0, 0);  // the most urgent: stops the step timer
  nvic_priority(kExti1, 0);
  nvic_enable(kExti0);
  nvic_enable(kExti1);
}

}  // namespace haloplot::fw

namespace {
void limit_irq(uint8_t motor) {
  using namespace haloplot::fw;
  chip::EXTI.PR = 1u << board::kLimitPin[motor];  // write 1 to clear
  if (handler) handler(motor);
}
}  // namespace

extern "C" void exti0_irq_handler() { limit_irq(0); }
extern "C" void exti1_irq_handler() { limit_irq(1); }
