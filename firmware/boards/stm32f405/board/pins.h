// The controller board's wiring: which pin does what. One place, so a different board is a
// different copy of this file.
//
//   PD0, PD1   STEP, motor 0 and 1          (push-pull outputs, one BSRR store per edge)
//   PD2, PD3   DIR, motor 0 and 1
//   PD4        ENABLE, both drivers, active low
//   PA6        pen servo PWM, TIM3_CH1 (AF2), 50 Hz
//   PA9, PA10  host link USART1 TX, RX (AF7), 115200 8N1
//   PE0, PE1   limit switches, motor 0 and 1, to ground, pulled up: EXTI0, EXTI1
#pragma once
#include <stdint.h>

#include "haloplot/hal/stepper_axis.h"  // hal/: hal::kMotors

namespace haloplot::fw::board {

inline constexpr uint32_t kStepPin[hal::kMotors] = {0, 1}, kDirPin[hal::kMotors] = {2, 3},
                          kEnablePin = 4;
inline constexpr uint32_t kServoPin = 6, kServoAf = 2;
inline constexpr uint32_t kUsartTxPin = 9, kUsartRxPin = 10, kUsartAf = 7, kUsartBaud = 115200;
inline constexpr uint32_t kLimitPin[hal::kMotors] = {0, 1};

// Servo pulse widths, microseconds: pen up and pen down (a hobby servo's 1-2 ms range).
inline constexpr uint32_t kServoUpUs = 1200, kServoDownUs = 1800, kServoPeriodUs = 20000;

}  // namespace haloplot::fw::board
