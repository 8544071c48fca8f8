#include "drivers/step_timer.h"

namespace haloplot::fw {
namespace {

constexpr uint32_t kMaxReload = 0x00FFFFFFu;  // 24-bit counter
constexpr uint32_t kMinCycles = 32;           // never arm less than the interrupt's exit
uint32_t cycles_per_tick = chip::kCoreHz / 1000000;
uint32_t remaining = 0;  // cycles of a long delay not yet armed

// Restart the counter for `cycles` from the moment `elapsed` cycles ago.
void arm(uint32_t cycles, uint32_t elapsed) {
  using namespace chip;
  if (cycles > kMaxReload) {
    remaining = cycles - kMaxReload;
    cycles = kMaxReload;
  } else {
    remaining = 0;
  }
  const uint32_t left = cycles > elapsed + kMinCycles ? cycles - elapsed : kMinCycles;
  SYST.RVR = left - 1;
  SYST.CVR = 0;  // any write restarts the count from RVR
}

}  // namespace

Status step_timer_init(uint32_t tick_hz, uint32_t time_scale) {
  if (tick_hz == 0 || time_scale == 0 || chip::kCoreHz % tick_hz != 0 ||
      (chip::kCoreHz / tick_hz) % time_scale != 0)
    return Status::kBadParameter;
  cycles_per_tick = chip::kCoreHz / tick_hz / time_scale;
  chip::systick_priority(1);  // above the USART: a late step is a motion error
  return Status::kOk;
}

void step_timer_start(uint32_t first_delay) {
  using namespace chip;
  SYST.CSR = 0;
  SYST.RVR = kMaxReload;
  SYST.CVR = 0;
  arm(first_delay * cycles_per_tick, 0);
  SYST.CSR = SYST_CSR_ENABLE | SYST_CSR_TICKINT | SYST_CSR_CLKSOURCE;
}

void step_timer_stop() {
  chip::SYST.CSR = 0;
  remaining = 0;
}

bool step_timer_chunk_pending() {
  if (remaining == 0) return false;
  arm(remaining, chip::SYST.RVR - chip::SYST.CVR);
  return true;
}

// In the interrupt: the counter reloaded when it fired; RVR - CVR cycles have passed since.
void step_timer_next(uint32_t delay) {
  arm(delay * cycles_per_tick, chip::SYST.RVR - chip::SYST.CVR);
}

}  // namespace haloplot::fw
