#include "drivers/gpio.h"

namespace haloplot::fw {
namespace {

void set_mode(chip::GPIO_Regs& port, uint32_t pin, uint32_t mode) {
  port.MODER = (port.MODER & ~(3u << (2 * pin))) | (mode << (2 * pin));
}
void set_af(chip::GPIO_Regs& port, uint32_t pin, uint32_t af) {
  chip::reg& afr = port.AFR[pin / 8];
  afr = (afr & ~(0xFu << (4 * (pin % 8)))) | (af << (4 * (pin % 8)));
  set_mode(port, pin, chip::GPIO_MODER_AF);
}

}  // namespace

void gpio_init() {
  using namespace chip;
  RCC.AHB1ENR |= RCC_AHB1ENR_GPIOAEN | RCC_AHB1ENR_GPIODEN | RCC_AHB1ENR_GPIOEEN;
  step_pins_low();
  drivers_enable(false);
  for (uint8_t m = 0; m < hal::kMotors; ++m) {
    set_mode(GPIOD, board::kStepPin[m], GPIO_MODER_OUTPUT);
    set_mode(GPIOD, board::kDirPin[m], GPIO_MODER_OUTPUT);
    set_mode(GPIOE, board::kLimitPin[m], GPIO_MODER_INPUT);
    GPIOE.PUPDR = (GPIOE.PUPDR & ~(3u << (2 * board::kLimitPin[m]))) |
                  (GPIO_PUPDR_PULLUP << (2 * board::kLimitPin[m]));
  }
  set_mode(GPIOD, board::kEnablePin, GPIO_MODER_OUTPUT);
  set_af(GPIOA, board::kServoPin, board::kServoAf);
  set_af(GPIOA, board::kUsartTxPin, board::kUsartAf);
  set_af(GPIOA, board::kUsartRxPin, board::kUsartAf);
}

}  // namespace haloplot::fw
