// Reset and the vector table for the STM32F405 (Cortex-M4F). No C library start-up code: we
// copy .data, zero .bss and .ccm, paint the stack (for the high-water mark), enable the FPU
// (the core needs none, but compiler-generated code for other parts may) and call main().
#include <stdint.h>

extern "C" {
extern uint32_t __data_start, __data_end, __data_load, __bss_start, __bss_end, __ccm_start,
    __ccm_end, __stack_top, __stack_limit;
extern void (*__init_array_start[])(), (*__init_array_end[])();
int main();
[[noreturn]] void reset_handler();
void default_handler();
// The controller's step interrupt (firmware/app): SysTick is the step clock.
void step_timer_irq() __attribute__((weak, alias("default_handler")));
// Peripheral interrupts the drivers use (drivers/); unused ones stay on the default.
void exti0_irq_handler() __attribute__((weak, alias("default_handler")));
void exti1_irq_handler() __attribute__((weak, alias("default_handler")));
void usart1_irq_handler() __attribute__((weak, alias("default_handler")));
}

namespace {
constexpr uint32_t kStackPaint = 0xA5A5A5A5u;
}

extern "C" void default_handler() {
  for (;;) {
  }
}

extern "C" void reset_handler() {
  for (uint32_t *src = &__data_load, *dst = &__data_start; dst < &__data_end;) *dst++ = *src++;
  for (uint32_t* p = &__bss_start; p < &__bss_end; ++p) *p = 0;
  for (uint32_t* p = &__ccm_start; p < &__ccm_end; ++p) *p = 0;
  // Paint the stack below the current frame so firmware can measure its high-water mark.
  // The current stack pointer, less a margin for this frame, bounds the painted range.
  uint32_t sp;
  __asm__ volatile("mov %0, sp" : "=r"(sp));
  for (uint32_t* p = &__stack_limit; reinterpret_cast<uint32_t>(p) < sp - 256; ++p)
    *p = kStackPaint;
  // CPACR: full access to CP10/CP11 (the FPU), as RM0090 / the Cortex-M4 TRM describe.
  *reinterpret_cast<volatile uint32_t*>(0xE000ED88u) |= (0xFu << 20);
  for (auto f = __init_array_start; f < __init_array_end; ++f) (*f)();
  main();
  for (;;) {
  }
}

// Stack bytes never touched since boot: painted words still intact, from the bottom up.
extern "C" uint32_t stack_unused_bytes() {
  uint32_t n = 0;
  for (const uint32_t* p = &__stack_limit; p < &__stack_top && *p == kStackPaint; ++p) n += 4;
  return n;
}

// The first 16 system exceptions; peripheral interrupts are added by the drivers that use them.
__attribute__((section(".vectors"), used)) void (*const vector_table[16])() = {
    reinterpret_cast<void (*)()>(&__stack_top),
    reset_handler,
    default_handler,  // NMI
    default_handler,  // HardFault
    default_handler,  // MemManage
    default_handler,  // BusFault
    default_handler,  // UsageFault
    nullptr,
    nullptr,
    nullptr,
    nullptr,
    default_handler,  // SVCall
    default_handler,  // DebugMonitor
    nullptr,
    default_handler,  // PendSV
    step_timer_irq,   // SysTick: the step timer (drivers/step_timer.h)
};

// The 82 peripheral interrupts (RM0090 table 61), placed right after the system exceptions
// by the linker script. Built at compile time: the numbers are the manual's positions.
namespace {
using Handler = void (*)();
struct PeripheralVectors {
  Handler v[82];
};
constexpr PeripheralVectors make_peripheral_vectors() {
  PeripheralVectors t{};
  for (Handler& h : t.v) h = default_handler;
  t.v[6] = exti0_irq_handler;
  t.v[7] = exti1_irq_handler;
  t.v[37] = usart1_irq_handler;
  return t;
}
}  // namespace
__attribute__((section(".vectors.irq"), used)) const PeripheralVectors peripheral_vectors =
    make_peripheral_vectors();
