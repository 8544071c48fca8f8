// Reset and the trap handler for QEMU's RISC-V virt machine (RV32, machine mode, -bios none):
// the stack pointer, the trap vector, the portable C runtime start (firmware/platform), then
// main(). Any trap (an illegal instruction, a misaligned or bad access) reports its cause over
// semihosting and ends the run, so a test fails at once instead of hanging. CSRs are written as
// .insn, so no Zicsr extension need be named in -march (which would change the multilib).
#include <stdint.h>

#include "platform/c_runtime.h"
#include "platform/console.h"
#include "platform/semihosting.h"

extern "C" {
int main();
[[noreturn]] void rv32_reset();
[[noreturn]] void rv32_trap();

// The reset vector jumps here, the first word of RAM (the linker script puts .text.start there).
__attribute__((naked, section(".text.start"))) void _start() {
  __asm__ volatile(
      "la sp, __stack_top\n"
      "la t0, rv32_trap\n"
      ".insn i 0x73, 1, x0, t0, 0x305\n"  // csrw mtvec, t0
      "j rv32_reset\n");
}

void rv32_reset() {
  haloplot::fw::start_c_runtime();  // .data, .bss, the stack's paint (platform/c_runtime.h)
  haloplot::fw::run_static_constructors();
  haloplot::fw::semihost_exit(main());
}

__attribute__((aligned(4))) void rv32_trap() {
  uint32_t cause, pc;
  __asm__ volatile(".insn i 0x73, 2, %0, x0, 0x342" : "=r"(cause));  // csrr mcause
  __asm__ volatile(".insn i 0x73, 2, %0, x0, 0x341" : "=r"(pc));     // csrr mepc
  char line[80];
  char* p = haloplot::fw::append(line, "rv32: trap, mcause=");
  p = haloplot::fw::append_u64(p, cause);
  p = haloplot::fw::append(p, " mepc=");
  p = haloplot::fw::append_u64(p, pc);
  p = haloplot::fw::append(p, "\n");
  haloplot::fw::semihost_write(line, uint32_t(p - line));
  haloplot::fw::semihost_exit(3);
}
}
