// Reset and the vector table for the MPS2 AN385 (Cortex-M3, no FPU, no CCM). No C library
// start-up code: copy .data, zero .bss, paint the stack (for the high-water mark), call main().
#include <stdint.h>

extern "C" {
extern uint32_t __data_start, __data_end, __data_load, __bss_start, __bss_end, __stack_top,
    __stack_limit;
extern void (*__init_array_start[])(), (*__init_array_end[])();
int main();
[[noreturn]] void reset_handler();
void default_handler();
// Peripheral interrupts the drivers use (drivers/); unused ones stay on the default.
void uart0_rx_irq_handler() __attribute__((weak, alias("default_handler")));
void timer0_irq_handler() __attribute__((weak, alias("default_handler")));
void gpio0_pin8_irq_handler() __attribute__((weak, alias("default_handler")));
void gpio0_pin9_irq_handler() __attribute__((weak, alias("default_handler")));
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
  // Paint the stack below the current frame (less a margin for this frame).
  uint32_t sp;
  __asm__ volatile("mov %0, sp" : "=r"(sp));
  for (uint32_t* p = &__stack_limit; reinterpret_cast<uint32_t>(p) < sp - 256; ++p)
    *p = kStackPaint;
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
