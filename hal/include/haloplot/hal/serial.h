// A byte stream to the host: the USART of the controller's job link (on the host, the
// simulator's link is a socket and needs none of this). Not on the step path: the main loop
// polls it. A board provides static functions (board_hal.h), checked at compile time.
//
//   struct MyBoard {
//     static void serial_init(uint32_t baud);
//     static bool serial_read(uint8_t* byte);                 // false when nothing is waiting
//     static void serial_write(const uint8_t* bytes, uint32_t n);
//     static uint32_t serial_overruns();                      // bytes lost (the CRC then fails)
//   };
#pragma once
#include <stdint.h>

#include "haloplot/hal/detect.h"

namespace haloplot::hal {

HALOPLOT_HAL_MEMBER(HasSerialInit, H::serial_init(uint32_t{115200}))
HALOPLOT_HAL_MEMBER(HasSerialRead,
                    static_cast<bool>(H::serial_read(static_cast<uint8_t*>(nullptr))))
HALOPLOT_HAL_MEMBER(HasSerialWrite, H::serial_write(static_cast<const uint8_t*>(nullptr), 0u))
HALOPLOT_HAL_MEMBER(HasSerialOverruns, static_cast<uint32_t>(H::serial_overruns()))

template <typename B>
constexpr bool check_board_serial() {
  static_assert(HasSerialInit<B>::value, "the board has no static void serial_init(uint32_t baud)");
  static_assert(HasSerialRead<B>::value,
                "the board has no static bool serial_read(uint8_t* byte) "
                "(hal/include/haloplot/hal/serial.h)");
  static_assert(HasSerialWrite<B>::value,
                "the board has no static void serial_write(const uint8_t*, uint32_t)");
  static_assert(HasSerialOverruns<B>::value, "the board has no static uint32_t serial_overruns()");
  return true;
}

}  // namespace haloplot::hal
