#include "drivers/step_timer.h"

#include "chip/cmsdk.h"

extern "C" void step_timer_irq();  // the controller's (firmware/app)

namespace haloplot::fw {
namespace {

constexpr uint32_t kMaxReload = 0xFFFFFFFFu;
constexpr uint32_t kMinCycles = 8;  // never arm less than the interrupt's exit (40 ns each)
uint32_t cycles_per_tick = chip::kSysclkHz / 1000000;
uint64_t remaining = 0;  // cycles of a long delay not yet armed

// Reload the counter for `cycles` from the moment `elapsed` cycles ago.
void arm(uint64_t cycles, uint32_t elapsed) {
  uint32_t now = kMaxReload;
  if (cycles > kMaxReload) {
    remaining = cycles - kMaxReload;
  } else {
    remaining = 0;
    now = uint32_t(cycles);
  }
  chip::TIMER0.RELOAD = now > elapsed + kMinCycles ? now - elapsed : kMinCycles;
}

// Cycles since the counter reached 0 and reloaded.
uint32_t elapsed() { return chip::TIMER0.RELOAD - chip::TIMER0.VALUE; }

}  // namespace

Status step_timer_init(uint32_t tick_hz, uint32_t time_scale) {
  if (tick_hz == 0 || time_scale == 0 || chip::kSysclkHz % tick_hz != 0 ||
      (chip::kSysclkHz / tick_hz) % time_scale != 0)
    return Status::kBadParameter;
  cycles_per_tick = chip::kSysclkHz / tick_hz / time_scale;
  chip::nvic_priority(chip::kTimer0, 1);  // above the UART: a late step is a motion error
  chip::nvic_enable(chip::kTimer0);
  return Status::kOk;
}

void step_timer_start(uint32_t first_delay) {
  using namespace chip;
  TIMER0.CTRL = 0;
  TIMER0.INTSTATUS = 1;
  arm(uint64_t{first_delay} * cycles_per_tick, 0);
  TIMER0.CTRL = TIMER_CTRL_EN | TIMER_CTRL_IRQEN;
}

void step_timer_stop() {
  chip::TIMER0.CTRL = 0;
  chip::TIMER0.INTSTATUS = 1;
  remaining = 0;
}

bool step_timer_chunk_pending() {
  if (remaining == 0) return false;
  arm(remaining, elapsed());
  return true;
}

void step_timer_next(uint32_t delay) { arm(uint64_t{delay} * cycles_per_tick, elapsed()); }

}  // namespace haloplot::fw

// Timer 0's interrupt: acknowledge first (the line is level: it would fire again on return),
// then the controller's step.
extern "C" void timer0_irq_handler() {
  haloplot::fw::chip::TIMER0.INTSTATUS = 1;
  step_timer_irq();
}
