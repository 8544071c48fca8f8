// A byte stream to the host (USART on the controller, a pipe or file in simulation).
//
//   struct MySerial {
//     bool read(uint8_t* byte);       // false when nothing is waiting
//     bool write(uint8_t byte);       // false when the transmit buffer is full
//   };
#pragma once
