#include "drivers/watchdog.h"

#include "chip/cmsdk.h"

namespace haloplot::fw {

void watchdog_start() {
  using namespace chip;
  WDOG_LOCK = WDOG_UNLOCK_KEY;
  WDOG.LOAD = kSysclkHz / 2;  // 0.5 s
  WDOG.CONTROL = WDOG_CONTROL_INTEN | WDOG_CONTROL_RESEN;
  WDOG_LOCK = 0;  // any other value locks it again
}

void watchdog_kick() {
  chip::WDOG_LOCK = chip::WDOG_UNLOCK_KEY;
  chip::WDOG.INTCLR = 1;  // clears the interrupt and restarts the count from LOAD
  chip::WDOG_LOCK = 0;
}

}  // namespace haloplot::fw
