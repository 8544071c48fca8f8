// The pen servo on TIM3 channel 1: 50 Hz PWM, the pulse width selects pen up or down. The
// motion queue already waits the servo's travel and settle time after each change, so
// setting the compare register is all a pen change does.
#pragma once

namespace haloplot::fw {

void servo_init();
void servo_pen(bool down);

}  // namespace haloplot::fw
