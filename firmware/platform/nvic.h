// The ARMv7-M interrupt controller (NVIC) and system handler priorities, the same on every
// Cortex-M3 and M4 board: set/clear enable, set pending, priority (ARMv7-M ARM B3.4). Each
// board's chip header names its interrupt numbers.
#pragma once
#include <stdint.h>

namespace haloplot::fw::armv7m {

inline void nvic_enable(uint32_t irq) {
  reinterpret_cast<volatile uint32_t*>(0xE000E100u)[irq / 32] = 1u << (irq % 32);
}
inline void nvic_disable(uint32_t irq) {
  reinterpret_cast<volatile uint32_t*>(0xE000E180u)[irq / 32] = 1u << (irq % 32);
}
// Set an interrupt pending from software (NVIC_ISPR): it runs as if its line had fired.
inline void nvic_set_pending(uint32_t irq) {
  reinterpret_cast<volatile uint32_t*>(0xE000E200u)[irq / 32] = 1u << (irq % 32);
}
// Interrupt priority (8 bits per IRQ; both boards implement the upper 3 or 4): lower is more
// urgent. Priorities 0-7 read the same on either.
inline void nvic_priority(uint32_t irq, uint8_t prio) {
  reinterpret_cast<volatile uint8_t*>(0xE000E400u)[irq] = uint8_t(prio << 5);
}
// System handler priority for SysTick (SHPR3 bits 31:24).
inline void systick_priority(uint8_t prio) {
  reinterpret_cast<volatile uint8_t*>(0xE000ED23u)[0] = uint8_t(prio << 5);
}

}  // namespace haloplot::fw::armv7m
