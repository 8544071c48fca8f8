// The CMSDK peripherals of the MPS2 AN385 FPGA image that the firmware uses, written from the
// Cortex-M System Design Kit TRM (DDI 0479) and the AN385 application note (memory map and
// interrupt numbers), with their register names; no vendor header is used. All run from the
// 25 MHz SYSCLK.
#pragma once
#include <stddef.h>
#include <stdint.h>

#include "platform/nvic.h"

namespace haloplot::fw::chip {

using reg = volatile uint32_t;

// APB timer (DDI 0479 4.3): a 32-bit down-counter; the interrupt fires as it reaches 0, and it
// reloads from RELOAD. Writing RELOAD also loads the counter.
struct ApbTimer_Regs {
  reg CTRL, VALUE, RELOAD, INTSTATUS;  // INTSTATUS: write 1 to clear
};
inline constexpr uint32_t TIMER_CTRL_EN = 1u << 0, TIMER_CTRL_IRQEN = 1u << 3;

// Dual timer (DDI 0479 4.4), timer 1 only: free-running 32-bit down-counter.
struct DualTimer_Regs {
  reg LOAD, VALUE, CONTROL, INTCLR, RIS, MIS, BGLOAD;
};
static_assert(offsetof(DualTimer_Regs, BGLOAD) == 0x18);
inline constexpr uint32_t DUALTIMER_CONTROL_SIZE32 = 1u << 1, DUALTIMER_CONTROL_EN = 1u << 7;

// APB UART (DDI 0479 4.2).
struct ApbUart_Regs {
  reg DATA, STATE, CTRL, INTSTATUS, BAUDDIV;  // INTSTATUS: write 1 to clear
};
inline constexpr uint32_t UART_STATE_TXFULL = 1u << 0, UART_STATE_RXFULL = 1u << 1,
                          UART_STATE_RXOVERRUN = 1u << 3;
inline constexpr uint32_t UART_CTRL_TXEN = 1u << 0, UART_CTRL_RXEN = 1u << 1,
                          UART_CTRL_RXIRQEN = 1u << 3;
inline constexpr uint32_t UART_INT_RX = 1u << 1, UART_INT_RXOVERRUN = 1u << 3;

// APB watchdog (DDI 0479 4.5): counts LOAD down; the first time out raises its interrupt
// (the NMI on the AN385), the second resets the chip when RESEN is set. INTCLR restarts it.
struct Watchdog_Regs {
  reg LOAD, VALUE, CONTROL, INTCLR;
};
inline constexpr uint32_t WDOG_CONTROL_INTEN = 1u << 0, WDOG_CONTROL_RESEN = 1u << 1;
inline reg& WDOG_LOCK = *reinterpret_cast<reg*>(0x40008C00u);
inline constexpr uint32_t WDOG_UNLOCK_KEY = 0x1ACCE551u;

// AHB GPIO (DDI 0479 4.1). MASKLOWBYTE: a store to 0x400 + (mask << 2) writes only the pins in
// `mask` (bits 0-7), in one bus write: the set/reset a step edge wants, without a
// read-modify-write.
struct AhbGpio_Regs {
  reg DATA, DATAOUT, reserved0[2], OUTENSET, OUTENCLR, ALTFUNCSET, ALTFUNCCLR, INTENSET, INTENCLR,
      INTTYPESET, INTTYPECLR, INTPOLSET, INTPOLCLR, INTSTATUS;  // INTSTATUS: W1C
};
static_assert(offsetof(AhbGpio_Regs, INTSTATUS) == 0x38);
inline reg& gpio_masked(uint32_t base, uint32_t mask) {
  return *reinterpret_cast<reg*>(base + 0x400u + (mask << 2));
}

inline constexpr uint32_t kTimer0Base = 0x40000000u, kGpio0Base = 0x40010000u;
inline ApbTimer_Regs& TIMER0 = *reinterpret_cast<ApbTimer_Regs*>(kTimer0Base);
inline DualTimer_Regs& DUALTIMER1 = *reinterpret_cast<DualTimer_Regs*>(0x40002000u);
inline ApbUart_Regs& UART0 = *reinterpret_cast<ApbUart_Regs*>(0x40004000u);
inline Watchdog_Regs& WDOG = *reinterpret_cast<Watchdog_Regs*>(0x40008000u);
inline AhbGpio_Regs& GPIO0 = *reinterpret_cast<AhbGpio_Regs*>(kGpio0Base);

// Interrupt numbers (AN385 table "interrupt map"): UART 0 receive, timer 0, and GPIO 0's
// per-pin interrupts from 16 (pin n is 16 + n). The NVIC is the architecture's.
enum Irq : uint32_t { kUart0Rx = 0, kTimer0 = 8, kGpio0Pin0 = 16 };
using armv7m::nvic_enable;
using armv7m::nvic_priority;
using armv7m::nvic_set_pending;

inline constexpr uint32_t kSysclkHz = 25000000;

}  // namespace haloplot::fw::chip
