// The host link on UART0: received bytes go from the receive interrupt into a ring the main
// loop drains; sending waits for the one-byte transmit buffer (replies are short).
#pragma once
#include <stdint.h>

namespace haloplot::fw {

void uart_init(uint32_t baud);
bool uart_read(uint8_t* byte);  // the next received byte, if any
void uart_write(const uint8_t* bytes, uint32_t n);
uint32_t uart_overruns();  // bytes lost: the UART's own overrun or a full ring

}  // namespace haloplot::fw
