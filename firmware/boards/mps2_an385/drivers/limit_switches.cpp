#include "drivers/limit_switches.h"

#include "board/pins.h"
#include "chip/cmsdk.h"

namespace haloplot::fw {
namespace {
void (*handler)(uint8_t) = nullptr;
}

void limit_switches_init(void (*on_trigger)(uint8_t motor)) {
  using namespace chip;
  handler = on_trigger;
  for (uint8_t m = 0; m < hal::kMotors; ++m) {
    const uint32_t bit = 1u << board::kLimitPin[m];
    GPIO0.INTTYPESET = bit;  // edge
    GPIO0.INTPOLCLR = bit;   // falling: the switch pulls the pin to ground
    GPIO0.INTENSET = bit;
    const uint32_t irq = kGpio0Pin0 + board::kLimitPin[m];
    nvic_priority(irq, 0);  // the most urgent: stops the step timer
    nvic_enable(irq);
  }
}

}  // namespace haloplot::fw

namespace {
void limit_irq(uint8_t motor) {
  using namespace haloplot::fw;
  chip::GPIO0.INTSTATUS = 1u << board::kLimitPin[motor];  // write 1 to clear
  if (handler) handler(motor);
}
}  // namespace

extern "C" void gpio0_pin8_irq_handler() { limit_irq(0); }
extern "C" void gpio0_pin9_irq_handler() { limit_irq(1); }
