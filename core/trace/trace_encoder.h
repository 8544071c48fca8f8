// The step-trace text encoder, freestanding so the firmware and the host simulator write the
// same bytes for the same steps (the format is in the README and host_sim/sim/trace.h).
// Each motor's steps are run-length encoded as (T0, COUNT, DT, DDT, DIR): ticks T0, T0 + DT,
// T0 + 2 DT + DDT, ... A run closes when the direction changes or a gap breaks the pattern.
#pragma once
#include <stdint.h>

#include "motion/machine.h"

namespace haloplot {

struct CharSink {
  void (*write)(void* context, const char* text, uint32_t length);
  void* context;
};

class TraceEncoder {
 public:
  TraceEncoder(CharSink sink, const Machine& m);  // writes the header
  void step(uint64_t tick, uint8_t motor, bool backward);
  void pen(uint64_t tick, bool down);
  void finish(uint64_t end_tick);  // closes the open runs and writes "end"

 private:
  struct Run {
    uint64_t t0 = 0, last = 0, count = 0;
    int64_t dt = 0, ddt = 0, last_dt = 0;
    bool backward = false;
  };
  void flush(uint8_t motor);
  void put(const char* text);
  void put_u64(uint64_t v);
  void put_i64(int64_t v);

  CharSink sink_;
  Run runs_[2];
};

}  // namespace haloplot
