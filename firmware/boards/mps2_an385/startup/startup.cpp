// Reset and the vector table for the MPS2 AN385 (Cortex-M3, no FPU, no CCM): the portable C
// runtime start (platform/c_runtime.h), then main().
#include <stdint.h>

#include "platform/c_runtime.h"

extern "C" {
int main();
[[noreturn]] void reset_handler();
void default_handler();
// Peripheral interrupts the drivers use (drivers/); unused ones stay on the default.
void uart0_rx_irq_handler() __attribute__((weak, alias("default_handler")));
void timer0_irq_handler() __attribute__((weak, alias("default_handler")));
void gpio0_pin8_irq_handler() __attribute__((weak, alias("default_handler")));
void gpio0_pin9_irq_handler() __attribute__((weak, alias("default_handler")));
}

extern "C" void default_handler() {
  for (;;) {
  }
}

extern "C" void reset_handler() {
  haloplot::fw::start_c_runtime();  // .data, .bss, the stack's paint (platform/c_runtime.h)
  haloplot::fw::run_static_constructors();
  main();
  for (;;) {
  }
}

// The first 16 system exceptions. The NMI is the watchdog's first time out: it stays on the
// default handler, so the second one resets the board.
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
    default_handler,  // SysTick: unused here (the step clock is timer 0)
};

// The AN385's 32 interrupts, placed right after the system exceptions by the linker script.
// Built at compile time: the numbers are the application note's (chip/cmsdk.h).
namespace {
using Handler = void (*)();
struct PeripheralVectors {
  Handler v[32];
};
constexpr PeripheralVectors make_peripheral_vectors() {
  PeripheralVectors t{};
  for (Handler& h : t.v) h = default_handler;
  t.v[0] = uart0_rx_irq_handler;
  t.v[8] = timer0_irq_handler;  // the step clock (drivers/step_timer.cpp)
  t.v[16 + 8] = gpio0_pin8_irq_handler;
  t.v[16 + 9] = gpio0_pin9_irq_handler;
  return t;
}
}  // namespace
__attribute__((section(".vectors.irq"), used)) const PeripheralVectors peripheral_vectors =
    make_peripheral_vectors();
