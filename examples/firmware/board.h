// The example's board: an MPS2 AN386 (a Cortex-M4 at 25 MHz, CMSDK peripherals) as the motion
// runner sees it, the static functions haloplot's hal/include/haloplot/hal/board_hal.h asks of a
// board. Wiring, on GPIO 0: STEP of motor 0 and 1 on pins 0 and 1, their DIR on 2 and 3, the
// drivers' ENABLE (active low) on 4, the pen solenoid on 5. The step clock is the APB timer 0
// (interrupt 8).
#pragma once
#include <haloplot/hal/board_hal.h>
#include <stdint.h>

namespace example {

inline volatile uint32_t& reg(uint32_t address) {
  return *reinterpret_cast<volatile uint32_t*>(address);
}

// GPIO 0's masked byte access: a store to 0x400 + 4 * mask changes only the pins in `mask`, in
// one bus write (no read-modify-write to race with the interrupt).
inline void gpio_write(uint32_t mask, uint32_t value) { reg(0x40010400u + (mask << 2)) = value; }

// Timer 0: counts RELOAD down at 25 MHz and interrupts as it reaches 0, then reloads.
// Writing RELOAD also restarts the count.
constexpr uint32_t kTimerCtrl = 0x40000000u, kTimerValue = 0x40000004u, kTimerReload = 0x40000008u,
                   kTimerIntClear = 0x4000000Cu;
constexpr uint32_t kSysclkHz = 25000000;

struct Mps2Board {
  static inline uint32_t cycles_per_tick = 25;
  static inline uint64_t remaining = 0;  // cycles of a long delay not yet armed

  static void init() {
    gpio_write(0x3F, 0x10);   // STEP low, drivers off (ENABLE high), pen up
    reg(0x40010010u) = 0x3F;  // OUTENSET: pins 0-5 are outputs
  }
  static void step_high(uint8_t motor) { gpio_write(1u << motor, 1u << motor); }
  static void steps_low() { gpio_write(3, 0); }
  static void set_dir(uint8_t motor, bool backward) {
    gpio_write(4u << motor, backward ? 4u << motor : 0);
  }
  static void enable_drivers(bool on) { gpio_write(0x10, on ? 0 : 0x10); }
  static void pen_init() { pen_set(false); }
  static void pen_set(bool down) { gpio_write(0x20, down ? 0x20 : 0); }

  // The step clock: the plan's ticks (tick_hz a second) in timer cycles, `scale` times fast.
  static haloplot::Status timer_init(haloplot::TickRate tick, haloplot::TimeScale time_scale) {
    const uint32_t tick_hz = tick.hz, scale = time_scale.factor;
    if (tick_hz == 0 || scale == 0 || kSysclkHz % (uint64_t{tick_hz} * scale) != 0)
      return haloplot::Status::kBadParameter;
    cycles_per_tick = kSysclkHz / tick_hz / scale;
    reg(0xE000E100u) = 1u << 8;  // NVIC: enable interrupt 8
    return haloplot::Status::kOk;
  }
  static void timer_start(uint32_t first_delay) {
    reg(kTimerCtrl) = 0;
    reg(kTimerIntClear) = 1;
    arm(uint64_t{first_delay} * cycles_per_tick, 0);
    reg(kTimerCtrl) = 0x9;  // enable, interrupt enable
  }
  // From the interrupt: the next delay counts from the last one's end, not from now.
  static void timer_next(uint32_t delay) { arm(uint64_t{delay} * cycles_per_tick, elapsed()); }
  static void timer_stop() {
    reg(kTimerCtrl) = 0;
    reg(kTimerIntClear) = 1;
    remaining = 0;
  }
  // A delay beyond the 32-bit counter (171 s at 25 MHz) runs in pieces; each interrupt but
  // the last arms the next piece and is otherwise ignored.
  static bool timer_chunk_pending() {
    if (remaining == 0) return false;
    arm(remaining, elapsed());
    return true;
  }

 private:
  static uint32_t elapsed() { return reg(kTimerReload) - reg(kTimerValue); }
  static void arm(uint64_t cycles, uint32_t already) {
    uint32_t now = 0xFFFFFFFFu;
    remaining = cycles > now ? cycles - now : 0;
    if (cycles <= now) now = uint32_t(cycles);
    reg(kTimerReload) = now > already + 8 ? now - already : 8;  // never 0: that stops it
  }
};
static_assert(haloplot::hal::check_motion_board<Mps2Board>(), "the example's board");

}  // namespace example
