// Step traces: what the motors and the pen did, tick by tick, as text that compresses well.
//
//   haloplot-trace 1
//   tick_hz 1000000
//   kinematics corexy            cartesian | corexy
//   steps 1/1                    motor steps per plot step
//   backlash 0 0                 slack per motor, in motor steps
//   p TICK down|up               a pen change
//   m MOTOR T0 COUNT DT DDT DIR  COUNT steps of MOTOR in direction DIR (+ or -) at ticks
//                                T0, T0 + DT, T0 + 2 DT + DDT, ...: the gap grows by DDT each
//                                step, so cruising and steady ramps take one line each
//   end TICK                     the tick of the last event
//
// Lines appear in the order runs close, which is fixed for a given job: the same job always
// gives the same bytes.
#pragma once
#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

#include "io/input_error.h"
#include "motion/machine.h"
#include "trace/trace_encoder.h"

namespace haloplot::host {

struct StepEvent {
  uint64_t tick;
  uint8_t motor;  // 0, 1; 2 = pen
  bool flag;      // motor: backward; pen: down
};

// Writes a trace to a stream through the core's encoder (the firmware uses the same one).
class TraceWriter {
 public:
  TraceWriter(std::ostream& out, const Machine& m);
  void step(uint64_t tick, uint8_t motor, bool backward) { encoder_.step(tick, motor, backward); }
  void pen(uint64_t tick, bool down) { encoder_.pen(tick, down); }
  void finish(uint64_t end_tick) { encoder_.finish(end_tick); }

 private:
  static void write(void* context, const char* text, uint32_t length);
  TraceEncoder encoder_;
};

struct Trace {
  Machine machine;                // tick_hz, kinematics, steps, backlash
  std::vector<StepEvent> events;  // every step and pen change, in time order
  uint64_t end_tick = 0;
};

// Reads a trace; more than max_events steps and pen changes is an error (a damaged count in a
// run line must not exhaust memory: 16 bytes an event).
InputError read_trace(std::istream& in, const std::string& name, Trace* out,
                      uint64_t max_events = 200000000);

}  // namespace haloplot::host
