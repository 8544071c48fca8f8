// Output and exit through ARM semihosting: a BKPT 0xAB that the debugger, here QEMU with
// -semihosting-config enable=on, services. For running under QEMU only: on a board without a
// debugger attached the BKPT faults.
#pragma once
#include <stdint.h>

namespace example {

inline int32_t semihost(uint32_t operation, const void* argument) {
  register uint32_t r0 __asm__("r0") = operation;
  register const void* r1 __asm__("r1") = argument;
  __asm__ volatile("bkpt 0xAB" : "+r"(r0) : "r"(r1) : "memory");
  return int32_t(r0);
}

// SYS_WRITE to the console, which is the file ":tt" opened for writing (SYS_OPEN, mode 4).
inline void semihost_write(const char* text, uint32_t length) {
  static int32_t console = -1;
  if (console < 0) {
    static const char name[] = ":tt";
    const uint32_t open[3] = {uint32_t(reinterpret_cast<uintptr_t>(name)), 4, 3};
    console = semihost(0x01, open);
  }
  const uint32_t write[3] = {uint32_t(console), uint32_t(reinterpret_cast<uintptr_t>(text)),
                             length};
  semihost(0x05, write);
}

// SYS_EXIT_EXTENDED: QEMU exits with `status`.
[[noreturn]] inline void semihost_exit(int status) {
  const uint32_t exit[2] = {0x20026, uint32_t(status)};  // ADP_Stopped_ApplicationExit
  semihost(0x20, exit);
  for (;;) {
  }
}

// Text gathered in 1 KB and written in one call (each call stops the CPU for the host).
class Console {
 public:
  void write(const char* text, uint32_t length) {
    for (uint32_t i = 0; i < length; ++i) {
      if (n_ == sizeof buffer_) flush();
      buffer_[n_++] = text[i];
    }
  }
  void print(const char* text) {
    uint32_t n = 0;
    while (text[n] != 0) ++n;
    write(text, n);
  }
  void print(uint32_t value) {
    char digits[10];
    uint32_t n = 0;
    do {
      digits[n++] = char('0' + value % 10);
      value /= 10;
    } while (value != 0);
    while (n > 0) write(&digits[--n], 1);
  }
  void flush() {
    if (n_ > 0) semihost_write(buffer_, n_);
    n_ = 0;
  }

 private:
  char buffer_[1024] = {};  // every member initialised: a static Console needs no constructor
  uint32_t n_ = 0;
};

}  // namespace example
