// Shared by the QEMU self-test images: how a failure is reported (a "fw FAILED:" line naming
// the stage and the status, then exit 1 over semihosting) and the recording HAL that hands
// every step and pen change to the trace encoder at the virtual tick.
#pragma once
#include <stdint.h>

#include "haloplot/status/status.h"
#include "haloplot/trace/trace_encoder.h"
#include "platform/console.h"
#include "platform/semihosting.h"

namespace haloplot::fw {

[[noreturn]] inline void selftest_fail(Console& console, const char* what, Status s) {
  char line[128];
  char* p = append(line, "fw FAILED: ");
  p = append(p, what);
  p = append(p, ": ");
  p = append(p, status_name(s));
  append(p, "\n");
  console.flush();
  semihost_print(line);
  semihost_exit(1);
}

struct TraceHal {
  uint64_t now = 0;
  bool backward[2] = {false, false};
  TraceEncoder* trace = nullptr;
  void set_direction(uint8_t m, bool b) { backward[m] = b; }
  void step(uint8_t m) { trace->step(now, m, backward[m]); }
  void pen(bool down) { trace->pen(now, down); }
};

}  // namespace haloplot::fw
