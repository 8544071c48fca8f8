// Reset and the vector table for the MPS2 AN386 (a Cortex-M4). Reset copies .data, clears
// .bss and calls main(): a C start-up, which runs no static constructors (.init_array). Every
// object in static storage here is constant-initialised (haloplot's MotionRunner among them:
// all zero, in .bss), so none is needed; the CTest `examples` checks that the image has no
// .init_array and that the runner's trace is haloplot sim's. The FPU stays off, as it is at
// reset: nothing here writes CPACR, and nothing in the image may use a floating-point register
// (a floating-point instruction would fault, which fault_handler reports).
#include <stdint.h>

#include "semihosting.h"

extern "C" {
extern uint32_t __data_start[], __data_end[], __data_load[], __bss_start[], __bss_end[];
int main();
void timer0_irq_handler();  // main.cpp: the step clock's interrupt

[[noreturn]] void reset_handler() {
  const uint32_t* from = __data_load;
  for (uint32_t* to = __data_start; to < __data_end;) *to++ = *from++;
  for (uint32_t* to = __bss_start; to < __bss_end;) *to++ = 0;
  main();
  example::semihost_exit(1);
}

// Any fault: say which and exit, so a test fails at once instead of hanging. The UsageFault
// NOCP bit (CFSR bit 19) is an FPU instruction run with the FPU off.
[[noreturn]] void fault_handler() {
  const uint32_t cfsr = *reinterpret_cast<volatile uint32_t*>(0xE000ED28u);
  example::Console out;
  out.print("example: fault, CFSR=");
  out.print(cfsr);
  if ((cfsr & (1u << 19)) != 0) out.print(" (an FPU instruction with the FPU off)");
  out.print("\n");
  out.flush();
  example::semihost_exit(3);
}

void unused_handler() { fault_handler(); }
}

namespace {

// The handlers after the initial stack pointer (the linker script writes that first word):
// the 15 system exceptions, then the AN386's 32 interrupts (its application note's numbers).
using Handler = void (*)();
struct Vectors {
  Handler entry[15 + 32];
};

constexpr Vectors make_vectors() {
  Vectors v{};
  for (Handler& h : v.entry) h = unused_handler;
  v.entry[0] = reset_handler;
  for (int i = 1; i <= 5; ++i) v.entry[i] = fault_handler;  // NMI, HardFault, MemManage, ...
  for (int i = 6; i <= 9; ++i) v.entry[i] = nullptr;        // reserved
  v.entry[12] = nullptr;                                    // reserved
  v.entry[15 + 8] = timer0_irq_handler;                     // interrupt 8: timer 0
  return v;
}

}  // namespace

__attribute__((section(".vectors"), used)) const Vectors vectors = make_vectors();
