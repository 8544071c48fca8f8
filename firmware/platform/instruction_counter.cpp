#include "platform/instruction_counter.h"

namespace haloplot::fw {
namespace {

// SysTick registers (ARMv7-M Architecture Reference Manual, B3.3).
volatile uint32_t& SYST_CSR = *reinterpret_cast<volatile uint32_t*>(0xE000E010u);
volatile uint32_t& SYST_RVR = *reinterpret_cast<volatile uint32_t*>(0xE000E014u);
volatile uint32_t& SYST_CVR = *reinterpret_cast<volatile uint32_t*>(0xE000E018u);
constexpr uint32_t kReload = 0x00FFFFFFu;
volatile uint32_t wraps = 0;

}  // namespace

void counter_start() {
  SYST_CSR = 0;
  SYST_RVR = kReload;
  SYST_CVR = 0;
  wraps = 0;
  SYST_CSR = 0x7u;  // ENABLE | TICKINT | CLKSOURCE = processor clock
}

uint64_t counter_ticks() {
  // Read wraps on both sides of the current value, so a wrap in between is not lost.
  uint32_t w, v;
  do {
    w = wraps;
    v = SYST_CVR;
  } while (w != wraps);
  return uint64_t{w} * (kReload + 1) + (kReload - v);
}

}  // namespace haloplot::fw

extern "C" void systick_handler() { ++haloplot::fw::wraps; }
