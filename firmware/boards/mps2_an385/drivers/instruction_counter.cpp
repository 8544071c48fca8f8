// The dual timer's timer 1, free-running down from 2^32 - 1 at the 25 MHz SYSCLK. Under QEMU
// -icount shift=0 a count is 40 ns of virtual time, 40 instructions. Timer 0 is the step clock.
#include "platform/instruction_counter.h"

#include "chip/cmsdk.h"

namespace haloplot::fw {
namespace {
uint32_t last = 0, high = 0;  // the software extension of the 32-bit count (counting up)
constexpr uint32_t kNsPerCount = 1000000000u / chip::kSysclkHz;
}  // namespace

void counter_start() {
  using namespace chip;
  DUALTIMER1.CONTROL = 0;
  DUALTIMER1.LOAD = 0xFFFFFFFFu;
  DUALTIMER1.CONTROL = DUALTIMER_CONTROL_SIZE32 | DUALTIMER_CONTROL_EN;  // free-running
  last = high = 0;
}

uint64_t counter_ticks() {
  // Called from the main loop only (not reentrant): a smaller reading means one wrap.
  const uint32_t now = 0xFFFFFFFFu - chip::DUALTIMER1.VALUE;
  if (now < last) ++high;
  last = now;
  return uint64_t{high} << 32 | now;
}

uint64_t ticks_to_instructions(uint64_t ticks) { return ticks * kNsPerCount; }

}  // namespace haloplot::fw
