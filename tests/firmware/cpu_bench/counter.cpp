// The instruction counter of the per-CPU benchmark under QEMU -icount shift=0 (one instruction
// per nanosecond of virtual time). Arm (mps2-an386): the CMSDK dual timer's timer 1 free-running
// at the 25 MHz SYSCLK, 40 instructions a count, as the MPS2 board's counter
// (firmware/boards/mps2_an385/drivers/instruction_counter.cpp). RISC-V (virt): the instret
// counter, which QEMU answers from the instruction count itself under -icount.
#include "platform/instruction_counter.h"

namespace haloplot::fw {
namespace {
uint64_t base = 0;
#if defined(__riscv)
uint64_t raw() {
  uint32_t hi, lo, again;
  do {  // the high half read twice: a carry between the reads is caught
    // csrr of instreth (0xC82), instret (0xC02), instreth, as .insn (startup.cpp says why; the
    // CSR number is a signed 12-bit immediate there)
    __asm__ volatile(".insn i 0x73, 2, %0, x0, -894" : "=r"(hi));
    __asm__ volatile(".insn i 0x73, 2, %0, x0, -1022" : "=r"(lo));
    __asm__ volatile(".insn i 0x73, 2, %0, x0, -894" : "=r"(again));
  } while (hi != again);
  return uint64_t{hi} << 32 | lo;
}
constexpr uint64_t kInstructionsPerCount = 1;
#else
struct DualTimer {
  volatile uint32_t LOAD, VALUE, CONTROL, INTCLR, RIS, MIS, BGLOAD;
};
DualTimer& timer1() { return *reinterpret_cast<DualTimer*>(0x40002000u); }
uint32_t last = 0, high = 0;  // the software extension of the 32-bit count (counting up)
uint64_t raw() {
  const uint32_t now = 0xFFFFFFFFu - timer1().VALUE;
  if (now < last) ++high;
  last = now;
  return uint64_t{high} << 32 | now;
}
constexpr uint64_t kInstructionsPerCount = 40;  // 1 GHz of virtual time / 25 MHz
#endif
}  // namespace

void counter_start() {
#if !defined(__riscv)
  timer1().CONTROL = 0;
  timer1().LOAD = 0xFFFFFFFFu;
  timer1().CONTROL = (1u << 1) | (1u << 7);  // 32-bit, enabled, free-running
  last = high = 0;
#endif
  base = raw();
}

uint64_t counter_ticks() { return raw() - base; }

uint64_t ticks_to_instructions(uint64_t ticks) { return ticks * kInstructionsPerCount; }

}  // namespace haloplot::fw
