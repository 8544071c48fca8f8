// The host link on USART1: received bytes go from the RXNE interrupt into a ring buffer, so
// none are lost while the main loop is busy (CUT on a large scene takes milliseconds, far
// longer than one byte time); the main loop drains it. Transmission is polled: replies are
// a few dozen bytes, sent only from the main loop.
#pragma once
#include <stdint.h>

namespace haloplot::fw {

void usart_init(uint32_t baud);
bool usart_read(uint8_t* byte);  // false when the ring is empty
void usart_write(const uint8_t* bytes, uint32_t n);
uint32_t usart_overruns();  // bytes lost to a full ring or a hardware overrun (the frame's
                            // CRC then fails and the host resends)

}  // namespace haloplot::fw
