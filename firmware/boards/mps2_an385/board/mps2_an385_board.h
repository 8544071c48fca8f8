// The MPS2 AN385 board (pins in board/pins.h, drivers in drivers/, all in boards/mps2_an385/)
// as the portable controller sees it: the static functions hal/include/haloplot/hal/board_hal.h
// asks of a board, each a forward to this board's driver.
#pragma once
#include <stdint.h>

#include "drivers/gpio.h"
#include "drivers/limit_switches.h"
#include "drivers/step_timer.h"
#include "drivers/uart.h"
#include "drivers/watchdog.h"
#include "haloplot/hal/step_clock.h"  // TickRate, TimeScale

namespace haloplot::fw {

struct Mps2An385Board {
  static void init() { gpio_init(); }
  // Stepper drivers on GPIO 0, one masked store each.
  static void step_high(uint8_t motor) { step_pin_high(motor); }
  static void steps_low() { step_pins_low(); }
  static void set_dir(uint8_t motor, bool backward) { dir_pin(motor, backward); }
  static void enable_drivers(bool on) { drivers_enable(on); }
  // A pen-lift solenoid on a GPIO pin.
  static void pen_init() { pen_solenoid(false); }
  static void pen_set(bool down) { pen_solenoid(down); }
  // The step clock on the APB timer 0.
  static Status timer_init(TickRate tick, TimeScale scale) {
    return step_timer_init(tick.hz, scale.factor);
  }
  static void timer_start(uint32_t first_delay) { step_timer_start(first_delay); }
  static void timer_next(uint32_t delay) { step_timer_next(delay); }
  static void timer_stop() { step_timer_stop(); }
  static bool timer_chunk_pending() { return step_timer_chunk_pending(); }
  // The host link on UART0.
  static constexpr uint32_t kSerialBaud = board::kUartBaud;
  static void serial_init(uint32_t baud) { uart_init(baud); }
  static bool serial_read(uint8_t* byte) { return uart_read(byte); }
  static void serial_write(const uint8_t* bytes, uint32_t n) { uart_write(bytes, n); }
  static uint32_t serial_overruns() { return uart_overruns(); }
  // Limit switches on GPIO 0's pin interrupts, the CMSDK watchdog.
  static void limits_init(void (*on_trigger)(uint8_t motor)) { limit_switches_init(on_trigger); }
  static void watchdog_start() { fw::watchdog_start(); }
  static void watchdog_kick() { fw::watchdog_kick(); }
  // Test images: "close" limit switch 0. QEMU maps no GPIO on this board, so this sets the
  // pin's interrupt pending in the NVIC: the real handler and stop path run.
  static void test_close_limit(uint8_t) {
    chip::nvic_set_pending(chip::kGpio0Pin0 + board::kLimitPin[0]);
  }
  // The link's frame timeout in instruction-counter ticks (25 MHz): 2 ms on the board, 100 ms
  // of QEMU's virtual time in the test image.
  static constexpr uint64_t kFrameIdleTicks = 50000, kTestFrameIdleTicks = 2500000;
  // Test images run the step clock this many times fast (25 MHz must stay a whole multiple
  // of tick_hz * scale: 5 cycles per 1 MHz tick).
  static constexpr uint32_t kTestTimeScale = 5;
};

}  // namespace haloplot::fw
