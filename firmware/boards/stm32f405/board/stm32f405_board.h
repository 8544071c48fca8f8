// The STM32F405 board (pins in board/pins.h, drivers in drivers/, all in boards/stm32f405/) as the
// portable controller sees it: the static functions hal/include/haloplot/hal/board_hal.h asks of a
// board, each a forward to the chip's driver. A port to another board writes its own such type over
// its own drivers and names it in board/board.h; firmware/app does not change.
#pragma once
#include <stdint.h>

#include "drivers/gpio.h"
#include "drivers/limit_switches.h"
#include "drivers/servo_pwm.h"
#include "drivers/step_timer.h"
#include "drivers/usart.h"
#include "drivers/watchdog.h"
#include "haloplot/hal/step_clock.h"  // TickRate, TimeScale

namespace haloplot::fw {

struct Stm32f405Board {
  static void init() { gpio_init(); }
  // Stepper drivers: PD0-PD4 (board/pins.h), one BSRR store each.
  static void step_high(uint8_t motor) { step_pin_high(motor); }
  static void steps_low() { step_pins_low(); }
  static void set_dir(uint8_t motor, bool backward) { dir_pin(motor, backward); }
  static void enable_drivers(bool on) { drivers_enable(on); }
  // The pen servo on TIM3.
  static void pen_init() { servo_init(); }
  static void pen_set(bool down) { servo_pen(down); }
  // The step clock on SysTick.
  static Status timer_init(TickRate tick, TimeScale scale) {
    return step_timer_init(tick.hz, scale.factor);
  }
  static void timer_start(uint32_t first_delay) { step_timer_start(first_delay); }
  static void timer_next(uint32_t delay) { step_timer_next(delay); }
  static void timer_stop() { step_timer_stop(); }
  static bool timer_chunk_pending() { return step_timer_chunk_pending(); }
  // The host link on USART1.
  static constexpr uint32_t kSerialBaud = board::kUsartBaud;
  static void serial_init(uint32_t baud) { usart_init(baud); }
  static bool serial_read(uint8_t* byte) { return usart_read(byte); }
  static void serial_write(const uint8_t* bytes, uint32_t n) { usart_write(bytes, n); }
  static uint32_t serial_overruns() { return usart_overruns(); }
  // Limit switches on EXTI0/1, the independent watchdog.
  static void limits_init(void (*on_trigger)(uint8_t motor)) { limit_switches_init(on_trigger); }
  static void watchdog_start() { fw::watchdog_start(); }
  static void watchdog_kick() { fw::watchdog_kick(); }
  // Test images: "close" limit switch 0. QEMU models neither the switch's pin nor EXTI's
  // software trigger, so this sets the EXTI0 interrupt pending in the NVIC: the real handler
  // and stop path run, as on a falling edge of PE0.
  static void test_close_limit(uint8_t) { chip::nvic_set_pending(chip::kExti0); }
  // The link's frame timeout in instruction-counter ticks (TIM5): 2 ms at its 84 MHz on the
  // chip; 100 ms of QEMU's 1 GHz virtual time in the test image.
  static constexpr uint64_t kFrameIdleTicks = 168000, kTestFrameIdleTicks = 100000000;
  // Test images run the step clock this many times fast (the core's 168 MHz must stay a whole
  // multiple of tick_hz * scale).
  static constexpr uint32_t kTestTimeScale = 8;
};

}  // namespace haloplot::fw
