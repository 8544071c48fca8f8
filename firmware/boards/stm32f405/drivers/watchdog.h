// The independent watchdog: if the main loop stops kicking it (a hang anywhere, including a
// stuck interrupt), the chip resets, the drivers' ENABLE pin goes to its reset state (off)
// and the motors stop. Timeout about 0.5 s from the 32 kHz LSI (RM0090 19.3).
#pragma once

namespace haloplot::fw {

void watchdog_start();
void watchdog_kick();

}  // namespace haloplot::fw
