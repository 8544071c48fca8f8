#include "drivers/usart.h"

#include "chip/stm32f405.h"

namespace haloplot::fw {
namespace {

constexpr uint32_t kRing = 2048;  // two of the largest frames
static_assert((kRing & (kRing - 1)) == 0, "power of two: free-running indices");
uint8_t ring[kRing];
volatile uint32_t head = 0, tail = 0;  // tail written by the interrupt, head by the main loop
volatile uint32_t overruns = 0;

}  // namespace

void usart_init(uint32_t baud) {
  using namespace chip;
  RCC.APB2ENR |= RCC_APB2ENR_USART1EN;
  USART1.BRR = (kApb2Hz + baud / 2) / baud;  // 16x oversampling: mantissa and fraction
  USART1.CR1 = USART_CR1_UE | USART_CR1_TE | USART_CR1_RE | USART_CR1_RXNEIE;
  nvic_priority(kUsart1, 2);
  nvic_enable(kUsart1);
}

bool usart_read(uint8_t* byte) {
  if (head == tail) return false;
  *byte = ring[head % kRing];
  head = head + 1;
  return true;
}

void usart_write(const uint8_t* bytes, uint32_t n) {
  using namespace chip;
  for (uint32_t i = 0; i < n; ++i) {
    while (!(USART1.SR & USART_SR_TXE)) {
    }
    USART1.DR = bytes[i];
  }
}

uint32_t usart_overruns() { return overruns; }

}  // namespace haloplot::fw

extern "C" void usart1_irq_handler() {
  using namespace haloplot::fw;
  using namespace haloplot::fw::chip;
  const uint32_t sr = USART1.SR;
  if (sr & (USART_SR_RXNE | USART_SR_ORE)) {
    const uint8_t b = uint8_t(USART1.DR);  // reading DR clears RXNE and ORE
    if (sr & USART_SR_ORE) overruns = overruns + 1;
    if (tail - head < kRing) {
      ring[tail % kRing] = b;
      tail = tail + 1;
    } else {
      overruns = overruns + 1;
    }
  }
}
