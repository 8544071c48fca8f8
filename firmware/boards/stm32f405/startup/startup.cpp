// Reset and the vector table for the STM32F405 (Cortex-M4F): the portable C runtime start,
// then .ccm zeroed, then main(). The FPU stays off, as it is at reset: the core and the
// firmware are compiled to use no FPU register, and every image's link is gated on it
// (cmake/check_no_float.cmake), so the step interrupt never stacks FPU state either.
#include <stdint.h>

#include "platform/c_runtime.h"

extern "C" {
extern uint32_t __ccm_start, __ccm_end;
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

extern "C" void default_handler() {
  for (;;) {
  }
}

extern "C" void reset_handler() {
  haloplot::fw::start_c_runtime();  // .data, .bss, the stack's paint (platform/c_runtime.h)
  for (uint32_t* p = &__ccm_start; p < &__ccm_end; ++p) *p = 0;
  haloplot::fw::run_static_constructors();
  main();
  for (;;) {
  }
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
