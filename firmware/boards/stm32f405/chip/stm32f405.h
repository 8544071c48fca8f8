// The few STM32F405 registers the firmware uses, written from the reference manual (RM0090)
// with its register and bit names; no vendor header or CMSIS package is available here.
// Each block is a struct laid out at the manual's offsets and placed at its base address
// from the memory map (RM0090 section 2.3, table 1).
#pragma once
#include <stddef.h>
#include <stdint.h>

#include "platform/nvic.h"

namespace haloplot::fw::chip {

using reg = volatile uint32_t;

// Reset and clock control (RM0090 7.3).
struct RCC_Regs {
  reg CR, PLLCFGR, CFGR, CIR, AHB1RSTR, AHB2RSTR, AHB3RSTR, reserved0, APB1RSTR, APB2RSTR,
      reserved1[2], AHB1ENR, AHB2ENR, AHB3ENR, reserved2, APB1ENR, APB2ENR;
};
static_assert(offsetof(RCC_Regs, AHB1ENR) == 0x30 && offsetof(RCC_Regs, APB2ENR) == 0x44);
inline constexpr uint32_t RCC_AHB1ENR_GPIOAEN = 1u << 0, RCC_AHB1ENR_GPIODEN = 1u << 3,
                          RCC_AHB1ENR_GPIOEEN = 1u << 4;
inline constexpr uint32_t RCC_APB1ENR_TIM3EN = 1u << 1, RCC_APB1ENR_TIM5EN = 1u << 3;
inline constexpr uint32_t RCC_APB2ENR_USART1EN = 1u << 4, RCC_APB2ENR_SYSCFGEN = 1u << 14;

// General-purpose I/O (RM0090 8.4).
struct GPIO_Regs {
  reg MODER, OTYPER, OSPEEDR, PUPDR, IDR, ODR, BSRR, LCKR, AFR[2];
};
static_assert(offsetof(GPIO_Regs, BSRR) == 0x18 && offsetof(GPIO_Regs, AFR) == 0x20);
inline constexpr uint32_t GPIO_MODER_INPUT = 0, GPIO_MODER_OUTPUT = 1, GPIO_MODER_AF = 2;
inline constexpr uint32_t GPIO_PUPDR_PULLUP = 1;

// General-purpose timers TIM2 to TIM5 (RM0090 18.4).
struct TIM_Regs {
  reg CR1, CR2, SMCR, DIER, SR, EGR, CCMR1, CCMR2, CCER, CNT, PSC, ARR, RCR, CCR1, CCR2, CCR3, CCR4,
      BDTR, DCR, DMAR, OR;
};
static_assert(offsetof(TIM_Regs, CNT) == 0x24 && offsetof(TIM_Regs, CCR1) == 0x34);
inline constexpr uint32_t TIM_CR1_CEN = 1u << 0, TIM_CR1_URS = 1u << 2, TIM_CR1_OPM = 1u << 3,
                          TIM_CR1_ARPE = 1u << 7;
inline constexpr uint32_t TIM_DIER_UIE = 1u << 0, TIM_SR_UIF = 1u << 0, TIM_EGR_UG = 1u << 0;
inline constexpr uint32_t TIM_CCMR1_OC1M_PWM1 = 6u << 4, TIM_CCMR1_OC1PE = 1u << 3;
inline constexpr uint32_t TIM_CCER_CC1E = 1u << 0;

// Universal synchronous asynchronous receiver transmitter (RM0090 30.6).
struct USART_Regs {
  reg SR, DR, BRR, CR1, CR2, CR3, GTPR;
};
static_assert(offsetof(USART_Regs, CR1) == 0x0C);
inline constexpr uint32_t USART_SR_ORE = 1u << 3, USART_SR_RXNE = 1u << 5, USART_SR_TC = 1u << 6,
                          USART_SR_TXE = 1u << 7;
inline constexpr uint32_t USART_CR1_RE = 1u << 2, USART_CR1_TE = 1u << 3,
                          USART_CR1_RXNEIE = 1u << 5, USART_CR1_UE = 1u << 13;

// Independent watchdog (RM0090 19.4).
struct IWDG_Regs {
  reg KR, PR, RLR, SR;
};
inline constexpr uint32_t IWDG_KR_START = 0xCCCC, IWDG_KR_UNLOCK = 0x5555, IWDG_KR_RELOAD = 0xAAAA;

// External interrupt controller and system configuration (RM0090 12.3, 9.2).
struct EXTI_Regs {
  reg IMR, EMR, RTSR, FTSR, SWIER, PR;
};
struct SYSCFG_Regs {
  reg MEMRMP, PMC, EXTICR[4];
};

inline RCC_Regs& RCC = *reinterpret_cast<RCC_Regs*>(0x40023800u);
inline GPIO_Regs& GPIOA = *reinterpret_cast<GPIO_Regs*>(0x40020000u);
inline GPIO_Regs& GPIOD = *reinterpret_cast<GPIO_Regs*>(0x40020C00u);
inline GPIO_Regs& GPIOE = *reinterpret_cast<GPIO_Regs*>(0x40021000u);
inline TIM_Regs& TIM3 = *reinterpret_cast<TIM_Regs*>(0x40000400u);
inline TIM_Regs& TIM5 = *reinterpret_cast<TIM_Regs*>(0x40000C00u);
inline USART_Regs& USART1 = *reinterpret_cast<USART_Regs*>(0x40011000u);
inline IWDG_Regs& IWDG = *reinterpret_cast<IWDG_Regs*>(0x40003000u);
inline EXTI_Regs& EXTI = *reinterpret_cast<EXTI_Regs*>(0x40013C00u);
inline SYSCFG_Regs& SYSCFG = *reinterpret_cast<SYSCFG_Regs*>(0x40013800u);

// Interrupt numbers (RM0090 table 61); the NVIC itself is the architecture's (platform/nvic.h).
enum Irq : uint32_t { kExti0 = 6, kExti1 = 7, kUsart1 = 37 };
using armv7m::nvic_disable;
using armv7m::nvic_enable;
using armv7m::nvic_priority;
using armv7m::nvic_set_pending;
using armv7m::systick_priority;

// SysTick (ARMv7-M B3.3): a 24-bit down-counter on the core clock, the step timer.
struct SysTick_Regs {
  reg CSR, RVR, CVR, CALIB;
};
inline SysTick_Regs& SYST = *reinterpret_cast<SysTick_Regs*>(0xE000E010u);
inline constexpr uint32_t SYST_CSR_ENABLE = 1u << 0, SYST_CSR_TICKINT = 1u << 1,
                          SYST_CSR_CLKSOURCE = 1u << 2;
// Clocks after the board's clock set-up: HSE 8 MHz, PLL to 168 MHz, APB1 = 42 MHz (timers
// x2 = 84 MHz), APB2 = 84 MHz (RM0090 6.2). QEMU's model does not emulate the PLL; the
// constants are what a flashed board runs at.
inline constexpr uint32_t kCoreHz = 168000000, kApb1TimerHz = 84000000, kApb2Hz = 84000000;

}  // namespace haloplot::fw::chip
