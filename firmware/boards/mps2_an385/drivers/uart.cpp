#include "drivers/uart.h"

#include "chip/cmsdk.h"
#include "platform/rx_ring.h"

namespace haloplot::fw {
namespace {

RxRing<2048> ring;  // two of the largest frames

}  // namespace

void uart_init(uint32_t baud) {
  using namespace chip;
  UART0.BAUDDIV = (kSysclkHz + baud / 2) / baud;  // 217 at 115200: the UART wants at least 16
  UART0.CTRL = UART_CTRL_TXEN | UART_CTRL_RXEN | UART_CTRL_RXIRQEN;
  nvic_priority(kUart0Rx, 2);
  nvic_enable(kUart0Rx);
}

bool uart_read(uint8_t* byte) { return ring.pop(byte); }

void uart_write(const uint8_t* bytes, uint32_t n) {
  using namespace chip;
  for (uint32_t i = 0; i < n; ++i) {
    while (UART0.STATE & UART_STATE_TXFULL) {
    }
    UART0.DATA = bytes[i];
  }
}

uint32_t uart_overruns() { return ring.overruns(); }

}  // namespace haloplot::fw

// The receive interrupt: one byte per interrupt (the UART holds one). Clear the interrupt
// first, then read DATA: a byte that lands in between raises it again.
extern "C" void uart0_rx_irq_handler() {
  using namespace haloplot::fw;
  using namespace haloplot::fw::chip;
  UART0.INTSTATUS = UART_INT_RX;
  const uint32_t state = UART0.STATE;
  if (!(state & UART_STATE_RXFULL)) return;
  const uint8_t b = uint8_t(UART0.DATA);
  if (state & UART_STATE_RXOVERRUN) {
    ring.count_overrun();
    UART0.STATE = UART_STATE_RXOVERRUN;  // write 1 to clear
  }
  ring.push(b);
}
