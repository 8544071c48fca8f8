// The controller's wiring on the MPS2 AN385: GPIO 0, one port for everything, so each step
// edge is one masked store (chip/cmsdk.h, MASKLOWBYTE).
//
//   GPIO0 0, 1   STEP, motor 0 and 1
//   GPIO0 2, 3   DIR, motor 0 and 1
//   GPIO0 4      ENABLE, both drivers, active low
//   GPIO0 5      pen lift solenoid (high: pen down); this board has no servo timer to spare
//   GPIO0 8, 9   limit switches, motor 0 and 1, to ground: falling-edge interrupts 24, 25
//   UART0        host link, 115200 8N1 (the MPS2's first serial port)
#pragma once
#include <stdint.h>

#include "haloplot/hal/stepper_axis.h"  // hal/: hal::kMotors

namespace haloplot::fw::board {

inline constexpr uint32_t kStepPin[hal::kMotors] = {0, 1}, kDirPin[hal::kMotors] = {2, 3},
                          kEnablePin = 4;
inline constexpr uint32_t kPenPin = 5;
inline constexpr uint32_t kLimitPin[hal::kMotors] = {8, 9};
inline constexpr uint32_t kUartBaud = 115200;

}  // namespace haloplot::fw::board
