// The C runtime's start, the same on every Cortex-M board and on the RISC-V test image (no C
// library start-up code): copy .data from flash, zero .bss, paint the stack below the current
// frame (for the high-water mark, platform/c_runtime.cpp stack_unused_bytes()), run the static
// constructors. The linker script defines the symbols. A board's reset handler calls it, adds
// what its chip needs (a CCM zeroed, say) and calls main().
#pragma once
#include <stdint.h>

extern "C" {
extern uint32_t __data_start, __data_end, __data_load, __bss_start, __bss_end, __stack_top,
    __stack_limit;
extern void (*__init_array_start[])(), (*__init_array_end[])();
uint32_t stack_unused_bytes();  // stack bytes never touched since boot
}

namespace haloplot::fw {

inline constexpr uint32_t kStackPaint = 0xA5A5A5A5u;

// Inline, so it runs in the reset handler's frame: painting stops 256 bytes below it.
__attribute__((always_inline)) inline void start_c_runtime() {
  for (uint32_t *src = &__data_load, *dst = &__data_start; dst < &__data_end;) *dst++ = *src++;
  for (uint32_t* p = &__bss_start; p < &__bss_end; ++p) *p = 0;
  uintptr_t sp;
#if defined(__riscv)
  __asm__ volatile("mv %0, sp" : "=r"(sp));
#else
  __asm__ volatile("mov %0, sp" : "=r"(sp));
#endif
  for (uint32_t* p = &__stack_limit; reinterpret_cast<uintptr_t>(p) < sp - 256; ++p)
    *p = kStackPaint;
}

inline void run_static_constructors() {
  for (auto f = __init_array_start; f < __init_array_end; ++f) (*f)();
}

}  // namespace haloplot::fw
