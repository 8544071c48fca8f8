// The CMSDK watchdog: kicked by the main loop; 0.5 s without a kick raises the NMI, another
// 0.5 s resets the board.
#pragma once

namespace haloplot::fw {

void watchdog_start();
void watchdog_kick();

}  // namespace haloplot::fw
