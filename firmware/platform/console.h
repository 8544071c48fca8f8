// Test-image output over semihosting, batched: each semihosting call traps to the host, so
// text is gathered in 1 KB and written in one call. Used for step traces and the "fw key=value"
// lines the QEMU tests read. Test images only (semihosting faults without a debugger).
#pragma once
#include <stdint.h>

#include "haloplot/trace/trace_encoder.h"

namespace haloplot::fw {

class Console {
 public:
  static void write(void* ctx, const char* text, uint32_t length);
  CharSink sink() { return CharSink{&Console::write, this}; }
  void flush();
  void stat(const char* key, uint64_t value);  // "fw key=value\n"

 private:
  char buf_[1024];
  uint32_t n_ = 0;
};

}  // namespace haloplot::fw
