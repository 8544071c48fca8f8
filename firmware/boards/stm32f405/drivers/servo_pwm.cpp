#include "drivers/servo_pwm.h"

#include "board/pins.h"
#include "chip/stm32f405.h"

namespace haloplot::fw {

void servo_init() {
  using namespace chip;
  RCC.APB1ENR |= RCC_APB1ENR_TIM3EN;
  TIM3.PSC = kApb1TimerHz / 1000000 - 1;  // 1 MHz: the compare value is in microseconds
  TIM3.ARR = board::kServoPeriodUs - 1;
  TIM3.CCMR1 = TIM_CCMR1_OC1M_PWM1 | TIM_CCMR1_OC1PE;
  TIM3.CCR1 = board::kServoUpUs;
  TIM3.CCER = TIM_CCER_CC1E;
  TIM3.EGR = TIM_EGR_UG;  // load the preloaded registers
  TIM3.CR1 = TIM_CR1_ARPE | TIM_CR1_CEN;
}

void servo_pen(bool down) { chip::TIM3.CCR1 = down ? board::kServoDownUs : board::kServoUpUs; }

}  // namespace haloplot::fw
