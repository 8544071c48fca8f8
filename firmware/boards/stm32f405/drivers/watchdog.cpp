#include "drivers/watchdog.h"

#include "chip/stm32f405.h"

namespace haloplot::fw {

void watchdog_start() {
  using namespace chip;
  IWDG.KR = IWDG_KR_START;
  IWDG.KR = IWDG_KR_UNLOCK;
  IWDG.PR = 2;      // LSI / 16: 2 kHz
  IWDG.RLR = 1000;  // 0.5 s
  IWDG.KR = IWDG_KR_RELOAD;
}

void watchdog_kick() { chip::IWDG.KR = chip::IWDG_KR_RELOAD; }

}  // namespace haloplot::fw
