#include "drivers/usart.h"

#include "chip/stm32f405.h"
#include "platform/rx_ring.h"

namespace haloplot::fw {
namespace {

RxRing<2048> ring;  // two of the largest frames

}  // namespace

void usart_init(uint32_t baud) {
  using namespace chip;
  RCC.APB2ENR |= RCC_APB2ENR_USART1EN;
  USART1.BRR = (kApb2Hz + baud / 2) / baud;  // 16x oversampling: mantissa and fraction
  USART1.CR1 = USART_CR1_UE | USART_CR1_TE | USART_CR1_RE | USART_CR1_RXNEIE;
  nvic_priority(kUsart1, 2);
  nvic_enable(kUsart1);
}

bool usart_read(uint8_t* byte) { return ring.pop(byte); }

void usart_write(const uint8_t* bytes, uint32_t n) {
  using namespace chip;
  for (uint32_t i = 0; i < n; ++i) {
    while (!(USART1.SR & USART_SR_TXE)) {
    }
    USART1.DR = bytes[i];
  }
}

uint32_t usart_overruns() { return ring.overruns(); }

}  // namespace haloplot::fw

extern "C" void usart1_irq_handler() {
  using namespace haloplot::fw;
  using namespace haloplot::fw::chip;
  const uint32_t sr = USART1.SR;
  if (sr & (USART_SR_RXNE | USART_SR_ORE)) {
    const uint8_t b = uint8_t(USART1.DR);  // reading DR clears RXNE and ORE
    if (sr & USART_SR_ORE) ring.count_overrun();
    ring.push(b);
  }
}
